#include "view/trail_colour.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace skylit::view {
namespace {

using Stops = std::array<glm::vec3, 5>;  // evenly spaced over [0, 1]

constexpr glm::vec3 rgb8(int hex) {
  return glm::vec3((hex >> 16) & 0xff, (hex >> 8) & 0xff, hex & 0xff) / 255.0f;
}

constexpr Stops kViridis{rgb8(0x440154), rgb8(0x3b528b), rgb8(0x21918c), rgb8(0x5ec962), rgb8(0xfde725)};
// RdBu reversed, so that u grows with the climb.
constexpr Stops kRdBu{rgb8(0x0571b0), rgb8(0x92c5de), rgb8(0xf7f7f7), rgb8(0xf4a582), rgb8(0xca0020)};

}  // namespace

glm::vec3 ramp_colour(TrailColour ramp, double u) {
  const Stops& stops = ramp == TrailColour::Altitude ? kViridis : kRdBu;
  const double x = (std::isnan(u) ? 0.0 : std::clamp(u, 0.0, 1.0)) * (stops.size() - 1);
  const std::size_t k = std::min(static_cast<std::size_t>(x), stops.size() - 2);
  const float f = static_cast<float>(x - static_cast<double>(k));
  return stops[k] + f * (stops[k + 1] - stops[k]);
}

double ramp_position(TrailColour ramp, double value, double lo, double hi) {
  const double u = ramp == TrailColour::Altitude ? (hi > lo ? (value - lo) / (hi - lo) : 0.5)
                                                 : 0.5 + 0.5 * value / kClimbClampMps;
  return std::clamp(u, 0.0, 1.0);
}

}  // namespace skylit::view
