#version 450
// The terrain's colour map: the renderer's `shaded` frame (band-major float32, NaN on
// nodata, 1 band grey or 3 bands R, G, B; gpu::GpuFrame) as the export's 8-bit display
// codes (tone curve applied), one RGBA8 texel per field texel, which the terrain's
// fragments filter bilinearly in one texture lookup (view/terrain_draw.h). Alpha 0 marks
// nodata; such a texel takes a valid neighbour's value, so that the lookup next to the
// surface's edge blends in nothing from beyond it. Needs display_code.glsl's defines.
#include "display_code.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(std430, binding = 0) readonly buffer Bands { float bands[]; };
layout(rgba8, binding = 0) writeonly uniform image2D colour_map;
uniform ivec2 field_size;
uniform int band_count;
uniform float display_scale;  // linear value -> display value
uniform int srgb;             // tone curve: 1 sRGB, 0 linear
uniform ivec2 origin;         // the first texel of the rectangle dispatched
uniform ivec2 extent;         // its size

vec3 linear_at(ivec2 ij) {
  vec3 v;
  for (int c = 0; c < 3; ++c) v[c] = bands[(min(c, band_count - 1) * field_size.y + ij.y) * field_size.x + ij.x];
  return v;
}

bool valid(vec3 v) { return !any(isnan(v)); }

void main() {
  if (any(greaterThanEqual(ivec2(gl_GlobalInvocationID.xy), extent))) return;
  ivec2 ij = origin + ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(ij, field_size))) return;
  vec3 v = linear_at(ij);
  float alpha = 1.0;
  if (!valid(v)) {
    alpha = 0.0;
    v = vec3(0.0);
    // The 4 edge neighbours first, then the corners.
    const ivec2 neighbours[8] = ivec2[8](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1), ivec2(1, 1),
                                         ivec2(-1, 1), ivec2(1, -1), ivec2(-1, -1));
    for (int k = 0; k < 8; ++k) {
      ivec2 n = ij + neighbours[k];
      if (any(lessThan(n, ivec2(0))) || any(greaterThanEqual(n, field_size))) continue;
      vec3 w = linear_at(n);
      if (valid(w)) {
        v = w;
        break;
      }
    }
  }
  vec3 code;
  for (int c = 0; c < 3; ++c) code[c] = displayCode(v[c] * display_scale, srgb != 0);
  imageStore(colour_map, ij, vec4(code / 255.0, alpha));
}
