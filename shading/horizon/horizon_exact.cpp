#include "shading/horizon/horizon_exact.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace skylit::horizon {

double exact_step_length(const terrain::HeightField& field, int row, Heading u, double step_texels) {
  // Texels crossed per metre along u, per axis; the larger one sets the step.
  const double per_m = std::max(std::abs(u.east) / field.dx(row), std::abs(u.north) / field.dy);
  return step_texels / per_m;
}

double exact_max_elevation(const terrain::HeightField& field, int i, int j, Heading u, const ExactMarch& o) {
  return exact_max_elevation_from(field, GridPoint{static_cast<double>(i), static_cast<double>(j)}, field.at(i, j), u, o);
}

double exact_max_elevation_from(const terrain::HeightField& field, GridPoint origin, double h0, Heading u,
                                const ExactMarch& o) {
  const double d_max = o.max_distance_m > 0.0 ? o.max_distance_m : dem_extent(field);
  const int row = std::clamp(static_cast<int>(std::lround(origin.y)), 0, field.height - 1);
  const double step = exact_step_length(field, row, u, o.step_texels);
  // atan is monotonic: keep the steepest slope, take one atan at the end.
  double best = -std::numeric_limits<double>::infinity();
  for (int k = 1;; ++k) {
    const double t = k * step;
    if (t > d_max * (1.0 + 1e-12)) break;
    const GridPoint p = ray_point(field, origin, u, t);
    if (!on_grid(field, p)) break;
    best = std::max(best, (bilinear_height(field, p) - o.curvature.drop(t) - h0) / t);
  }
  return std::isinf(best) ? best : std::atan(best);
}

}  // namespace skylit::horizon
