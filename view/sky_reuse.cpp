#include "view/sky_reuse.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <stdexcept>

namespace skylit::view {

SkyReuse::SkyReuse(double max_sun_angle_rad) : max_angle_(max_sun_angle_rad) {
  if (!(max_sun_angle_rad >= 0.0)) throw std::invalid_argument("SkyReuse: the sun's angle must be ≥ 0");
}

shading::Lighting SkyReuse::next(const shading::LightingRequest& request, shading::Lighting fresh) {
  // What places the sun is compared by the sun's angle instead.
  shading::LightingRequest timeless = request;
  timeless.time.clear();
  timeless.sun_azimuth_deg.reset();
  timeless.sun_elevation_deg.reset();
  if (made_ && request_ == timeless && made_->sky && fresh.sky && made_->colour == fresh.colour) {
    const glm::dvec3 a = made_->sun.direction, b = fresh.sun.direction;
    if (std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) <= max_angle_) {
      fresh.sky = made_->sky;
      return fresh;
    }
  }
  request_ = timeless;
  made_ = fresh;
  return fresh;
}

}  // namespace skylit::view
