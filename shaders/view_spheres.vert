#version 450
// Aircraft as their sphere sets: one screen-aligned square per sphere (instanced), large
// enough to hold its silhouette; the fragment stage intersects the sphere exactly. Each
// sphere falls with the ground under it (curvature_drop.glsl).
#include "curvature_drop.glsl"

layout(std430, binding = 2) readonly buffer Spheres { vec4 spheres[]; };  // x, y, z (m), radius
uniform mat4 view;
uniform mat4 proj;
uniform float exaggeration;

out vec3 view_pos;         // the square's point, view space
flat out vec4 view_sphere;  // centre (view space) and radius

void main() {
  vec4 s = spheres[gl_InstanceID];
  vec3 c = (view * vec4(s.xy, s.z * exaggeration - curvatureDrop(s.xy), 1.0)).xyz;
  vec2 corner = vec2(float(gl_VertexID & 1) * 2.0 - 1.0, float((gl_VertexID >> 1) & 1) * 2.0 - 1.0);
  // A square of half-side 1.5 r at the sphere's front covers its silhouette unless the
  // eye is within ~1.2 r of it; those spheres are not drawn.
  vec3 p = c + vec3(corner * 1.5 * s.w, s.w);
  view_pos = p;
  view_sphere = vec4(c, s.w);
  gl_Position = -c.z > 1.2 * s.w ? proj * vec4(p, 1.0) : vec4(2.0, 2.0, 2.0, 1.0);
}
