#include "shading/sky/sky_cie.h"

#include "shading/sh/sh_basis.h"
#include "shading/sky/sky_sh.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace skylit::sky {

namespace {

// ISO 15469 builds the 15 types from six gradation and six indicatrix groups.
constexpr double kGradation[6][2] = {{4.0, -0.70}, {1.1, -0.8}, {0.0, -1.0},
                                     {-1.0, -0.55}, {-1.0, -0.32}, {-1.0, -0.15}};
constexpr double kIndicatrix[6][3] = {{0.0, -1.0, 0.0},  {2.0, -1.5, 0.15}, {5.0, -2.5, 0.30},
                                      {10.0, -3.0, 0.45}, {16.0, -3.0, 0.30}, {24.0, -2.8, 0.15}};
// (gradation group, indicatrix group) of types 1..15, 1-based as in the standard.
constexpr int kTypeGroups[15][2] = {{1, 1}, {1, 2}, {2, 1}, {2, 2}, {3, 1}, {3, 2}, {3, 3}, {3, 4},
                                    {4, 2}, {4, 3}, {4, 4}, {5, 4}, {5, 5}, {6, 5}, {6, 6}};

void check_type(int type) {
  if (type < 1 || type > kCieTraditionalOvercast)
    throw std::invalid_argument("CIE sky: type " + std::to_string(type) + " not in 1..16");
}

}  // namespace

CieParams cie_standard_sky(int type) {
  if (type < 1 || type > 15) throw std::invalid_argument("CIE standard sky: type " + std::to_string(type) + " not in 1..15");
  const auto& g = kGradation[kTypeGroups[type - 1][0] - 1];
  const auto& i = kIndicatrix[kTypeGroups[type - 1][1] - 1];
  return {g[0], g[1], i[0], i[1], i[2]};
}

double cie_gradation(const CieParams& p, double Z) {
  const double c = std::cos(Z);
  return c > 0.0 ? 1.0 + p.a * std::exp(p.b / c) : 1.0;  // b < 0 for all types
}

double cie_indicatrix(const CieParams& p, double chi) {
  const double c = std::cos(chi);
  return 1.0 + p.c * (std::exp(p.d * chi) - std::exp(p.d * sh::kPi / 2.0)) + p.e * c * c;
}

double cie_relative_luminance(int type, double Z, double chi, double Zs) {
  check_type(type);
  if (type == kCieTraditionalOvercast) return (1.0 + 2.0 * std::cos(Z)) / 3.0;
  const CieParams p = cie_standard_sky(type);
  return cie_indicatrix(p, chi) * cie_gradation(p, Z) / (cie_indicatrix(p, Zs) * cie_gradation(p, 0.0));
}

CieSky::CieSky(int type, const glm::dvec3& sun_direction, const Rgb& zenith_radiance)
    : type_(type), zenith_(zenith_radiance) {
  check_type(type);
  const double elev = std::max(elevation_of(glm::normalize(sun_direction)), 0.0);
  shape_sun_ = direction_from_azimuth_elevation(azimuth_of(sun_direction), elev);
  sun_zenith_ = sh::kPi / 2.0 - elev;
}

CieSky CieSky::from_diffuse_horizontal(int type, const glm::dvec3& sun_direction, const Rgb& diffuse_horizontal) {
  CieSky s(type, sun_direction, Rgb(1.0));
  s.zenith_ = diffuse_horizontal / s.diffuse_horizontal_per_zenith();
  return s;
}

double CieSky::relative_luminance(const glm::dvec3& dir) const {
  if (dir.z <= 0.0) return 0.0;
  const double Z = std::acos(std::min(dir.z, 1.0));
  const double chi = std::acos(std::clamp(glm::dot(dir, shape_sun_), -1.0, 1.0));
  return cie_relative_luminance(type_, Z, chi, sun_zenith_);
}

Rgb CieSky::radiance(const glm::dvec3& dir) const { return zenith_ * relative_luminance(dir); }

bool CieSky::azimuthally_symmetric() const {
  if (type_ == kCieTraditionalOvercast) return true;
  const CieParams p = cie_standard_sky(type_);
  return p.c == 0.0 && p.e == 0.0;
}

double CieSky::diffuse_horizontal_per_zenith() const {
  const auto rule = upper_hemisphere_rule(kDenseNz, kDenseNphi);
  double s = 0.0;
  for (std::size_t k = 0; k < rule.dirs.size(); ++k)
    s += rule.weights[k] * rule.dirs[k].z * relative_luminance(rule.dirs[k]);
  return s;
}

}  // namespace skylit::sky
