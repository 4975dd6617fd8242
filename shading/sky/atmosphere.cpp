#include "shading/sky/atmosphere.h"

#include "shading/sh/sh_basis.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace skylit::sky {

namespace {
constexpr double kDeg = sh::kPi / 180.0;
constexpr double kAngstromAlpha = 1.3;
}  // namespace

void check_turbidity(double t) {
  if (!(t >= kMinTurbidity && t <= kMaxTurbidity))
    throw std::invalid_argument("sky: turbidity " + std::to_string(t) + " outside [1.7, 10]");
}

double kasten_young_air_mass(double elevation) {
  if (elevation < 0.0) return std::numeric_limits<double>::infinity();
  const double z_deg = 90.0 - elevation / kDeg;
  return 1.0 / (std::cos(z_deg * kDeg) + 0.50572 * std::pow(96.07995 - z_deg, -1.6364));
}

double kasten_rayleigh_thickness(double m) {
  if (m <= 20.0) return 1.0 / (6.6296 + m * (1.7513 + m * (-0.1202 + m * (0.0065 - m * 0.00013))));
  return 1.0 / (10.4 + 0.718 * m);
}

double angstrom_beta(double turbidity) { return 0.04608 * turbidity - 0.04586; }

double rayleigh_optical_depth(double lambda_um) { return 0.008735 * std::pow(lambda_um, -4.08); }

double aerosol_optical_depth(double lambda_um, double turbidity) {
  return angstrom_beta(turbidity) * std::pow(lambda_um, -kAngstromAlpha);
}

double esra_diffuse_horizontal(double elevation, double T) {
  check_turbidity(T);
  const double s = std::sin(std::max(elevation, 0.0));
  const double trd = -1.5843e-2 + 3.0543e-2 * T + 3.797e-4 * T * T;  // transmission at zenith sun
  double a0 = 2.6463e-1 - 6.1581e-2 * T + 3.1408e-3 * T * T;
  const double a1 = 2.0402 + 1.8945e-2 * T - 1.1161e-2 * T * T;
  const double a2 = -1.3025 + 3.9231e-2 * T + 8.5079e-3 * T * T;
  if (a0 * trd < 2e-3) a0 = 2e-3 / trd;  // ESRA's floor, active for large T_L
  return kSolarConstant * trd * (a0 + s * (a1 + s * a2));
}

double broadband_dni(double elevation, double turbidity) {
  check_turbidity(turbidity);
  if (elevation <= 0.0) return 0.0;
  const double m = kasten_young_air_mass(elevation);
  return kSolarConstant * std::exp(-0.8662 * turbidity * m * kasten_rayleigh_thickness(m));
}

Rgb direct_normal_irradiance(double elevation, double turbidity) {
  const double e = broadband_dni(elevation, turbidity);
  if (e == 0.0) return Rgb(0.0);
  const double m = kasten_young_air_mass(elevation);
  Rgb t;
  for (int c = 0; c < 3; ++c) {
    const double lam = kChannelWavelengths[c];
    t[c] = std::exp(-m * (rayleigh_optical_depth(lam) + aerosol_optical_depth(lam, turbidity)));
  }
  const double lum = luminance(t);
  if (lum <= 0.0) return Rgb(0.0);  // cannot happen for m ≤ 38, kept against underflow
  return t * (e / lum);
}

double Sun::solid_angle() { return 2.0 * sh::kPi * (1.0 - std::cos(kSunAngularRadius)); }

Rgb Sun::disc_radiance() const { return dni / solid_angle(); }

Sun make_sun(const glm::dvec3& direction, double turbidity) {
  Sun s;
  s.direction = direction;
  s.dni = direct_normal_irradiance(elevation_of(direction), turbidity);
  return s;
}

Rgb xyY_to_linear_srgb(double x, double y, double Y) {
  if (y <= 0.0 || Y <= 0.0) return Rgb(0.0);
  const double X = x / y * Y, Z = (1.0 - x - y) / y * Y;
  // IEC 61966-2-1 XYZ → linear sRGB (D65).
  const Rgb c{3.2404542 * X - 1.5371385 * Y - 0.4985314 * Z,
              -0.9692660 * X + 1.8760108 * Y + 0.0415560 * Z,
              0.0556434 * X - 0.2040259 * Y + 1.0572252 * Z};
  return glm::max(c, Rgb(0.0));
}

}  // namespace skylit::sky
