#version 450
// The terrain mesh: one patch of PATCH x PATCH quads per level-of-detail node
// (view/terrain_lod.h; one instance each), and skirts hung below the sides where nodes
// of different strides meet, so that their joins show no cracks (drawn per side). Each
// instance's node comes in per-instance attributes (a storage buffer indexed by
// gl_InstanceID is a load per SIMD lane on llvmpipe). Vertices read the heights from a
// texture: gl_VertexID = b * (PATCH + 3) + a over the patch with its ring.
// Needs PATCH (view/terrain_draw.cpp).
#include "curvature_drop.glsl"

layout(binding = 0) uniform sampler2D heights;  // r32f, texel (i, j) at (i, j)
uniform ivec2 field_size;
uniform vec2 spacing;       // dx, dy (m)
layout(location = 0) in ivec3 node;       // the patch's first vertex (texel i, j) and its stride
layout(location = 1) in float node_skirt;  // how far its ring hangs below its edge (m)
uniform float exaggeration;
uniform mat4 view_proj;

out vec2 texel;  // field texel coordinates (i, j), interpolated for the product lookup

void main() {
  int a = gl_VertexID % (PATCH + 3), b = gl_VertexID / (PATCH + 3);
  bool ring = a == 0 || b == 0 || a == PATCH + 2 || b == PATCH + 2;
  ivec2 local = clamp(ivec2(a, b) - 1, 0, PATCH);
  ivec2 ij = min(node.xy + local * node.z, field_size - 1);
  float h = texelFetch(heights, ij, 0).r;
  // The field's outer vertices move out by half a texel, so the surface covers every
  // texel's whole cell (the product clamps to the edge texel there).
  vec2 edge = vec2(ij.x == 0 ? -0.5 : (ij.x == field_size.x - 1 ? 0.5 : 0.0),
                   ij.y == 0 ? -0.5 : (ij.y == field_size.y - 1 ? 0.5 : 0.0));
  vec2 t = vec2(ij) + edge;
  vec2 xy = t * vec2(spacing.x, -spacing.y);
  // No neighbour lies beyond the field's edge: a skirt hung there (or the end of one
  // across a join) would only show below the edge, seen from outside the field.
  bool outer = ij.x == 0 || ij.y == 0 || ij.x == field_size.x - 1 || ij.y == field_size.y - 1;
  float z = h * exaggeration - curvatureDrop(xy) - (ring && !outer ? node_skirt : 0.0);
  texel = t;
  gl_Position = view_proj * vec4(xy, z, 1.0);
}
