#version 450
// Flight trails (view/trail_draw.cpp): line strips pulled from a storage buffer by
// gl_VertexID (glMultiDrawArrays counts from each strip's first vertex), z exaggerated
// like the aircraft's. Needs TRAIL_BINDING.
struct TrailVertex {
  vec4 position_time;  // field frame x, y, z (m, not exaggerated); seconds after the trail's first fix
  vec4 colour;         // sRGB display value, alpha 1
};
layout(std430, binding = TRAIL_BINDING) readonly buffer Trail { TrailVertex vertices[]; };
uniform mat4 view_proj;
uniform float exaggeration;

out float time_s;
out vec3 display;

void main() {
  TrailVertex v = vertices[gl_VertexID];
  time_s = v.position_time.w;
  display = v.colour.rgb;
  gl_Position = view_proj * vec4(v.position_time.xy, v.position_time.z * exaggeration, 1.0);
}
