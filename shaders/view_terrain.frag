#version 450
// The terrain's colour: its colour map (view_terrain_colour.comp: the `shaded` frame's
// display codes, as the export writes them) filtered bilinearly at the fragment's texel,
// so a top-down frame is the `shaded` raster. With NODATA 1, fragments nearer nodata than
// valid ground are dropped: the surface ends halfway to the first nodata texel. Without
// nodata the shader has no discard, so the rasterizer tests depth before shading
// (view/terrain_draw.cpp draws the nodes nearest first). Needs NODATA.

layout(binding = 1) uniform sampler2D colour_map;  // rgba8, linear filtering
uniform ivec2 field_size;

in vec2 texel;
out vec4 colour;

void main() {
  vec4 v = texture(colour_map, (texel + 0.5) / vec2(field_size));
#if NODATA
  if (v.a < 0.5) discard;
#endif
  colour = vec4(v.rgb, 1.0);
}
