#include "view/lighting_reuse.h"

#include "shading/sky/sky_model.h"

#include <cmath>
#include <stdexcept>

namespace skylit::view {
namespace {

using sky::angle_between;

bool close(double kept, double fresh) { return std::abs(fresh - kept) <= kLightingRelativeTolerance * std::abs(kept); }
bool close(const sky::Rgb& kept, const sky::Rgb& fresh) {
  return close(kept.r, fresh.r) && close(kept.g, fresh.g) && close(kept.b, fresh.b);
}

}  // namespace

LightingReuse::LightingReuse(double max_sun_angle_rad, double max_sky_angle_rad)
    : max_angle_(max_sun_angle_rad), max_sky_angle_(max_sky_angle_rad) {
  if (!(max_sun_angle_rad >= 0.0 && max_sky_angle_rad >= max_sun_angle_rad))
    throw std::invalid_argument("LightingReuse: the angles must be ≥ 0, the sky's at least the sun's");
}

shading::Lighting LightingReuse::next(const shading::LightingRequest& request, shading::Lighting fresh) {
  // What places the sun is compared by the sun's angle instead.
  shading::LightingRequest timeless = request;
  timeless.time.clear();
  timeless.sun_azimuth_deg.reset();
  timeless.sun_elevation_deg.reset();
  if (made_ && request_ == timeless && made_->sky && fresh.sky && made_->colour == fresh.colour &&
      angle_between(made_->sun.direction, fresh.sun.direction) <= max_sky_angle_) {
    if (angle_between(last_->sun.direction, fresh.sun.direction) <= max_angle_ && close(last_->sun.dni, fresh.sun.dni) &&
        close(last_->reference_irradiance, fresh.reference_irradiance))
      return *last_;
    fresh.sky = made_->sky;
    last_ = fresh;
    return fresh;
  }
  request_ = timeless;
  made_ = fresh;
  last_ = fresh;
  return fresh;
}

}  // namespace skylit::view
