#version 450
// Flight trails (view/trail_draw.cpp), each segment a screen-aligned quad `width_px`
// wide (core profile lines are 1 pixel): two triangles, six vertices per segment, pulled
// from a storage buffer by gl_VertexID. Segment g joins vertices g and g + 1; the draw
// counts only segments inside a polyline. z is exaggerated like the aircraft's and falls
// with the ground under it (curvature_drop.glsl). Needs TRAIL_BINDING.
#include "curvature_drop.glsl"

struct TrailVertex {
  vec4 position_time;  // field frame x, y, z (m, not exaggerated); seconds after the trail's first fix
  vec4 colour;         // sRGB display value, alpha 1
};
layout(std430, binding = TRAIL_BINDING) readonly buffer Trail { TrailVertex vertices[]; };
uniform mat4 view_proj;
uniform float exaggeration;
uniform float width_px;
uniform vec2 viewport;  // pixels

out float time_s;
out vec3 display;

vec4 clip_of(TrailVertex v) {
  vec2 xy = v.position_time.xy;
  return view_proj * vec4(xy, v.position_time.z * exaggeration - curvatureDrop(xy), 1.0);
}

void main() {
  int g = gl_VertexID / 6, corner = gl_VertexID % 6;
  TrailVertex a = vertices[g], b = vertices[g + 1];
  vec4 ca = clip_of(a), cb = clip_of(b);
  float ta = a.position_time.w, tb = b.position_time.w;
  // An end behind the eye moves along the segment to just in front of it (clip space is
  // linear along the segment), so the quad's direction on screen stays defined.
  const float near_w = 1e-3;
  if (ca.w < near_w && cb.w < near_w) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // wholly behind: outside the clip volume
    time_s = 0.0;
    display = vec3(0.0);
    return;
  }
  if (ca.w < near_w) {
    float s = (near_w - ca.w) / (cb.w - ca.w);
    ca = mix(ca, cb, s);
    ta = mix(ta, tb, s);
  } else if (cb.w < near_w) {
    float s = (near_w - cb.w) / (ca.w - cb.w);
    cb = mix(cb, ca, s);
    tb = mix(tb, ta, s);
  }
  vec2 sa = ca.xy / ca.w * viewport, sb = cb.xy / cb.w * viewport;  // twice the pixels
  vec2 along = sb - sa;
  along = dot(along, along) > 1e-12 ? normalize(along) : vec2(1.0, 0.0);
  vec2 across = vec2(-along.y, along.x) * width_px / viewport;  // half the width, in NDC
  // Corners 0 1 2 / 2 1 3 of (a -), (a +), (b -), (b +).
  int k = corner < 3 ? corner : corner == 3 ? 2 : corner == 4 ? 1 : 3;
  bool at_b = k >= 2;
  float side = (k & 1) == 0 ? -1.0 : 1.0;
  vec4 c = at_b ? cb : ca;
  gl_Position = c + vec4(side * across * c.w, 0.0, 0.0);
  time_s = at_b ? tb : ta;
  display = (at_b ? b : a).colour.rgb;
}
