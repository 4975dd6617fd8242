#version 450
// The terrain's colour: the renderer's `shaded` frame (band-major float32, NaN on
// nodata, 1 band grey or 3 bands R, G, B; gpu::GpuFrame) sampled bilinearly at the
// fragment's texel and tone-mapped as the export writes it, so a top-down frame is the
// `shaded` raster. Needs display_code.glsl's defines.
#include "display_code.glsl"

layout(std430, binding = 0) readonly buffer Bands { float bands[]; };
uniform ivec2 field_size;
uniform int band_count;
uniform float display_scale;  // linear value -> display value
uniform int srgb;             // tone curve: 1 sRGB, 0 linear

in vec2 texel;
out vec4 colour;

float band_at(int b, ivec2 ij) { return bands[(b * field_size.y + ij.y) * field_size.x + ij.x]; }

float bilinear(int b, vec2 t) {
  vec2 c = clamp(t, vec2(0.0), vec2(field_size - 1));
  ivec2 i0 = ivec2(floor(c));
  ivec2 i1 = min(i0 + 1, field_size - 1);
  vec2 f = c - vec2(i0);
  // A texel centre reads itself alone (the top-down frame equals the raster there).
  float v00 = band_at(b, i0);
  float v10 = f.x > 0.0 ? band_at(b, ivec2(i1.x, i0.y)) : v00;
  float v01 = f.y > 0.0 ? band_at(b, ivec2(i0.x, i1.y)) : v00;
  float v11 = f.x > 0.0 && f.y > 0.0 ? band_at(b, i1) : (f.x > 0.0 ? v10 : v01);
  // Nodata neighbours take the texel's own value: the surface ends at its last texel.
  if (isnan(v10)) v10 = v00;
  if (isnan(v01)) v01 = v00;
  if (isnan(v11)) v11 = v00;
  return mix(mix(v00, v10, f.x), mix(v01, v11, f.x), f.y);
}

void main() {
  vec3 code;
  for (int c = 0; c < 3; ++c) {
    float v = bilinear(min(c, band_count - 1), texel);
    if (isnan(v)) discard;
    code[c] = displayCode(v * display_scale, srgb != 0);
  }
  colour = vec4(code / 255.0, 1.0);
}
