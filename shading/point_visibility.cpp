#include "shading/point_visibility.h"

#include "shading/horizon/azimuth.h"
#include "shading/horizon/horizon_ray.h"
#include "shading/products.h"
#include "shading/sky/sun_disc.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace skylit::shading {
namespace {

constexpr double kHalfPi = std::numbers::pi / 2;

void validate(const PointVisibilityOptions& o) {
  horizon::validate(o.march);
  if (!(o.dense_step_texels > 0.0) || !std::isfinite(o.dense_step_texels))
    throw std::invalid_argument("point visibility: the dense step must be > 0 texels");
  if (!(o.sun_radius > 0.0 && o.sun_radius < std::numbers::pi / 4))
    throw std::invalid_argument("point visibility: sun radius must be in (0, π/4)");
}

const PointVisibilityOptions& validated(const PointVisibilityOptions& o) {
  validate(o);
  return o;
}

}  // namespace

horizon::GridPoint field_frame_texel(const terrain::HeightField& field, double x, double y) {
  const double j = -y / field.dy;
  const int row = std::clamp(static_cast<int>(std::lround(std::clamp(j, -1e9, 1e9))), 0, field.height - 1);
  return {x / field.dx(row), j};
}

double sea_level_horizon(double z, const horizon::EarthCurvature& curvature) {
  if (!curvature.enabled || !(z > 0.0)) return 0.0;
  const double r = curvature.effective_radius();
  return -std::acos(r / (r + z));
}

PointVisibilityMarcher::PointVisibilityMarcher(const terrain::HeightField& field, const PointVisibilityOptions& options)
    : field_(field), options_(validated(options)) {
  if (!options_.dense) marcher_.emplace(field_, options_.march);
}

double PointVisibilityMarcher::march(horizon::GridPoint origin, double z, double azimuth) const {
  const horizon::Heading u = horizon::heading_from_geographic(azimuth);
  const horizon::MarchOptions& o = options_.march;
  const double s = marcher_ ? marcher_->max_elevation_from(origin, z, u)
                            : horizon::exact_max_elevation_from(
                                  field_, origin, z, u, {options_.dense_step_texels, o.max_distance_m, o.curvature});
  // −∞ (no step on the grid) becomes the lowest elevation, so no result is infinite.
  return std::clamp(s, -kHalfPi, kHalfPi);
}

PointVisibility PointVisibilityMarcher::at(const glm::dvec3& point, std::optional<SunAngles> sun) const {
  if (!std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z))
    throw std::invalid_argument("point visibility: the point must be finite");
  if (sun && (!std::isfinite(sun->azimuth) || !std::isfinite(sun->elevation) || std::abs(sun->elevation) > kHalfPi))
    throw std::invalid_argument("point visibility: sun azimuth/elevation must be finite, |elevation| ≤ π/2");
  PointVisibility out;
  const horizon::GridPoint origin = field_frame_texel(field_, point.x, point.y);
  const double floor = sea_level_horizon(point.z, options_.march.curvature);
  if (horizon::on_grid(field_, origin)) {
    out.ground_m = horizon::bilinear_height(field_, origin);
    out.place = point.z < *out.ground_m ? PointPlace::BelowGround : PointPlace::Above;
  }
  if (out.place == PointPlace::BelowGround) {
    out.sky_view = out.sky_fraction = 0.0;
    if (sun) out.sun = SunVisibility{kHalfPi, true, sun->elevation - kHalfPi, 0.0, true};
    return out;
  }
  if (out.place == PointPlace::Above) {
    const int w = options_.march.azimuths;
    out.horizon.resize(w);
    for (int k = 0; k < w; ++k) out.horizon[k] = march(origin, point.z, horizon::band_azimuth(k, w));
    out.sky_view = skyview_from_horizon(out.horizon, {0.0, 0.0, 1.0});
    out.sky_fraction = svf_from_horizon(out.horizon);
  }
  if (sun) {
    SunVisibility s;
    const double terrain = out.place == PointPlace::Above ? march(origin, point.z, sun->azimuth) : -kHalfPi;
    s.terrain_horizon = terrain > floor;
    s.horizon = std::max(terrain, floor);
    s.margin = sun->elevation - s.horizon;
    s.visible_fraction = sky::sun_disc_fraction(sun->elevation, s.horizon, 0.0, options_.sun_radius);
    s.in_shadow = s.margin < 0.0;
    out.sun = s;
  }
  return out;
}

}  // namespace skylit::shading
