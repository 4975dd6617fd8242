#include "view/curvature_drop.h"

#include "shading/horizon/earth_curvature.h"

namespace skylit::view {

CurvatureDrop curvature_drop(bool curvature, const glm::dvec3& eye, double pixels_per_radian) {
  CurvatureDrop d;
  horizon::EarthCurvature geometric;
  geometric.enabled = curvature && pixels_per_radian > 0.0;
  geometric.refraction_k = 0.0;  // the drawn ground is where it is, not where refraction shows it
  d.per_m2 = geometric.drop_per_square_metre();
  d.eye_xy = {eye.x, eye.y};
  return d;
}

void set_curvature_uniforms(const gpu::GraphicsProgram& program, const CurvatureDrop& drop) {
  program.set("curvature", static_cast<float>(drop.per_m2));
  program.set("eye_xy", static_cast<float>(drop.eye_xy.x), static_cast<float>(drop.eye_xy.y));
}

}  // namespace skylit::view
