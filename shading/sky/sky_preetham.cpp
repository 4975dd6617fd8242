#include "shading/sky/sky_preetham.h"

#include "shading/sh/sh_basis.h"
#include "shading/sky/sky_sh.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace skylit::sky {

namespace preetham {

Perez coefficients(Channel ch, double T) {
  switch (ch) {
    case Channel::Y:
      return {0.1787 * T - 1.4630, -0.3554 * T + 0.4275, -0.0227 * T + 5.3251, 0.1206 * T - 2.5771,
              -0.0670 * T + 0.3703};
    case Channel::x:
      return {-0.0193 * T - 0.2592, -0.0665 * T + 0.0008, -0.0004 * T + 0.2125, -0.0641 * T - 0.8989,
              -0.0033 * T + 0.0452};
    case Channel::y:
      return {-0.0167 * T - 0.2608, -0.0950 * T + 0.0092, -0.0079 * T + 0.2102, -0.0441 * T - 1.6537,
              -0.0109 * T + 0.0529};
  }
  throw std::invalid_argument("preetham::coefficients: bad channel");
}

double perez(const Perez& p, double cos_theta, double gamma) {
  // B < 0 for every T ≥ 1.7, so e^{B/cos θ} → 0 at the horizon.
  const double grad = cos_theta > 0.0 ? 1.0 + p.A * std::exp(p.B / cos_theta) : 1.0;
  const double cg = std::cos(gamma);
  return grad * (1.0 + p.C * std::exp(p.D * gamma) + p.E * cg * cg);
}

double zenith_luminance_kcd(double T, double theta_s) {
  const double chi = (4.0 / 9.0 - T / 120.0) * (sh::kPi - 2.0 * theta_s);
  return (4.0453 * T - 4.9710) * std::tan(chi) - 0.2155 * T + 2.4192;
}

double zenith_chromaticity(Channel ch, double T, double ts) {
  // Rows multiply T², T, 1; columns θs³, θs², θs, 1 (Preetham appendix A.2).
  static constexpr double kX[3][4] = {{0.00166, -0.00375, 0.00209, 0.0},
                                      {-0.02903, 0.06377, -0.03202, 0.00394},
                                      {0.11693, -0.21196, 0.06052, 0.25886}};
  static constexpr double kY[3][4] = {{0.00275, -0.00610, 0.00317, 0.0},
                                      {-0.04214, 0.08970, -0.04153, 0.00516},
                                      {0.15346, -0.26756, 0.06670, 0.26688}};
  if (ch == Channel::Y) throw std::invalid_argument("zenith_chromaticity: x or y only");
  const auto& M = ch == Channel::x ? kX : kY;
  const double tv[3] = {T * T, T, 1.0}, sv[4] = {ts * ts * ts, ts * ts, ts, 1.0};
  double r = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) r += tv[i] * M[i][j] * sv[j];
  return r;
}

}  // namespace preetham

PreethamSky::PreethamSky(const glm::dvec3& sun_direction, double turbidity, PreethamLevel level,
                         double luminous_efficacy)
    : turbidity_(turbidity), efficacy_(luminous_efficacy) {
  check_turbidity(turbidity);
  if (!(luminous_efficacy > 0.0)) throw std::invalid_argument("PreethamSky: efficacy must be > 0");
  const double elev = elevation_of(glm::normalize(sun_direction));
  shape_sun_ = direction_from_azimuth_elevation(azimuth_of(sun_direction), std::max(elev, 0.0));
  const double ts = std::acos(std::clamp(shape_sun_.z, 0.0, 1.0));
  using preetham::Channel;
  const Channel chans[3] = {Channel::Y, Channel::x, Channel::y};
  for (int c = 0; c < 3; ++c) {
    coef_[c] = preetham::coefficients(chans[c], turbidity);
    denom_[c] = preetham::perez(coef_[c], 1.0, ts);
  }
  zenith_[1] = preetham::zenith_chromaticity(Channel::x, turbidity, ts);
  zenith_[2] = preetham::zenith_chromaticity(Channel::y, turbidity, ts);
  const double fade = twilight_factor(elev);
  if (level == PreethamLevel::Paper) {
    zenith_[0] = 1000.0 * preetham::zenith_luminance_kcd(turbidity, ts) / efficacy_ * fade;
  } else {
    // D / ∫ (Y/Y_z) cos θ dω; a midpoint-in-φ rule converges slowly only at the
    // circumsolar cusp, ≈1e-4 relative at this size.
    const auto rule = upper_hemisphere_rule(kDenseNz / 2, kDenseNphi / 2);
    double integral = 0.0;
    for (std::size_t k = 0; k < rule.dirs.size(); ++k) {
      const double g = std::acos(std::clamp(glm::dot(rule.dirs[k], shape_sun_), -1.0, 1.0));
      integral += rule.weights[k] * rule.dirs[k].z * ratio(0, rule.dirs[k].z, g);
    }
    zenith_[0] = esra_diffuse_horizontal(elev, turbidity) / integral * fade;
  }
}

double PreethamSky::ratio(int c, double cos_theta, double gamma) const {
  return preetham::perez(coef_[c], cos_theta, gamma) / denom_[c];
}

double PreethamSky::luminance_cd(const glm::dvec3& dir) const {
  if (dir.z <= 0.0 || zenith_[0] == 0.0) return 0.0;
  const double gamma = std::acos(std::clamp(glm::dot(dir, shape_sun_), -1.0, 1.0));
  return zenith_[0] * efficacy_ * ratio(0, dir.z, gamma);
}

glm::dvec2 PreethamSky::chromaticity(const glm::dvec3& dir) const {
  const double gamma = std::acos(std::clamp(glm::dot(dir, shape_sun_), -1.0, 1.0));
  const double cz = std::max(dir.z, 0.0);
  return {zenith_[1] * ratio(1, cz, gamma), zenith_[2] * ratio(2, cz, gamma)};
}

Rgb PreethamSky::radiance(const glm::dvec3& dir) const {
  const double Y = luminance_cd(dir) / efficacy_;
  if (Y <= 0.0) return Rgb(0.0);
  const glm::dvec2 xy = chromaticity(dir);
  return xyY_to_linear_srgb(xy.x, xy.y, Y);
}

}  // namespace skylit::sky
