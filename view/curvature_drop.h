// Earth's curvature at range, as the viewer draws it: the ground falls away from the eye
// by d² / (2R), d the horizontal distance from the eye. Whatever is drawn over the ground
// (the aircraft, their trails, the brush's pick ray) falls by the same, or it floats
// above the ground it shades (31 m at 20 km, 196 m at 50 km). The drop is the horizon
// march's (horizon::EarthCurvature) without refraction. GLSL twin:
// shaders/curvature_drop.glsl.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "gpu/graphics_program.h"

namespace skylit::view {

struct CurvatureDrop {
  double per_m2 = 0.0;  // 1 / (2R) (horizon::EarthCurvature, no refraction), or 0: no drop
  glm::dvec2 eye_xy{0.0};

  // The drop (m) at field-frame (x, y).
  double at(double x, double y) const {
    const double dx = x - eye_xy.x, dy = y - eye_xy.y;
    return per_m2 * (dx * dx + dy * dy);
  }
};

// The drop of a view from `eye`: none for orthographic views (pixels_per_radian 0) or
// with the curvature off.
CurvatureDrop curvature_drop(bool curvature, const glm::dvec3& eye, double pixels_per_radian);

// Sets curvature_drop.glsl's uniforms.
void set_curvature_uniforms(const gpu::GraphicsProgram& program, const CurvatureDrop& drop);

}  // namespace skylit::view
