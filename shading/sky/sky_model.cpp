#include "shading/sky/sky_model.h"

#include "shading/horizon/azimuth.h"
#include "shading/sh/sh_basis.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace skylit::sky {

namespace {
constexpr double kTwilightDecadesPerDegree = 0.4;
constexpr double kAstronomicalNight = -18.0 * sh::kPi / 180.0;
}  // namespace

double luminance(const Rgb& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

glm::dvec3 direction_from_azimuth_elevation(double azimuth, double elevation) {
  const double ce = std::cos(elevation);
  const auto h = horizon::heading_from_geographic(azimuth);
  return {ce * h.east, ce * h.north, std::sin(elevation)};
}

double azimuth_of(const glm::dvec3& d) {
  const double a = horizon::geographic_from_math(std::atan2(d.y, d.x));
  return a < 0.0 ? a + horizon::kTwoPi : a;
}

double elevation_of(const glm::dvec3& d) { return std::asin(std::clamp(d.z, -1.0, 1.0)); }

double angle_between(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));  // acos loses small angles
}

double twilight_factor(double sun_elevation) {
  if (sun_elevation >= 0.0) return 1.0;
  if (sun_elevation <= kAstronomicalNight) return 0.0;
  return std::pow(10.0, kTwilightDecadesPerDegree * sun_elevation * 180.0 / sh::kPi);
}

UniformSky::UniformSky(const Rgb& radiance) : radiance_(radiance) {}

Rgb UniformSky::radiance(const glm::dvec3& dir) const { return dir.z > 0.0 ? radiance_ : Rgb(0.0); }

}  // namespace skylit::sky
