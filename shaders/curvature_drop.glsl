// The drawn ground's fall from the eye, d^2 / (2 R): twin of view::CurvatureDrop
// (view/curvature_drop.h, which sets these uniforms). Coordinates relative to the eye keep
// float precision at range.

uniform float curvature;  // 1 / (2 R), or 0: no drop
uniform vec2 eye_xy;      // field frame (m)

float curvatureDrop(vec2 xy) {
  vec2 d = xy - eye_xy;
  return curvature * dot(d, d);
}
