#version 450
// The terrain's colour: its colour map (view_terrain_colour.comp: the `shaded` frame's
// linear display values) filtered bilinearly at the fragment's texel and tone-mapped as
// the export writes it, so a top-down frame is the `shaded` raster. With NODATA 1,
// fragments nearer nodata than valid ground are dropped: the surface ends halfway to the
// first nodata texel. Without nodata the shader has no discard, so the rasterizer tests
// depth before shading (view/terrain_draw.cpp draws the nodes nearest first). Needs
// NODATA and display_code.glsl's defines.
#include "display_code.glsl"

layout(binding = 1) uniform sampler2D colour_map;  // rgba32f, linear filtering
uniform ivec2 field_size;
uniform int srgb;  // tone curve: 1 sRGB, 0 linear

in vec2 texel;
out vec4 colour;

void main() {
  vec4 v = texture(colour_map, (texel + 0.5) / vec2(field_size));
#if NODATA
  if (v.a < 0.5) discard;
#endif
  vec3 code;
  for (int c = 0; c < 3; ++c) code[c] = displayCode(v[c], srgb != 0);
  colour = vec4(code / 255.0, 1.0);
}
