// Preetham, Shirley & Smits (1999), "A practical analytic model for daylight":
// Perez et al. (1993) distribution F(θ, γ) = (1 + A e^{B/cos θ})(1 + C e^{Dγ} + E cos²γ)
// for Y, x and y with coefficients linear in turbidity T (paper, appendix A.2),
// zenith luminance Y_z (kcd/m²) and zenith chromaticity x_z, y_z polynomials in
// T and the solar zenith angle θ_s. Colour: xyY → linear sRGB.
//
// Absolute level (PreethamLevel):
//   * Esra (default): the Perez shape is scaled so that the horizontal diffuse
//     irradiance equals the ESRA clear-sky diffuse model (atmosphere.h) for
//     T_L = T — the same model family as the sun's DNI, so sun and sky share
//     one energy budget. T = 3, sun at 60°: ≈108 W/m² (≈13.6 klx at 125 lm/W).
//   * Paper: Preetham's Y_z (cd/m²) divided by the luminous efficacy. This is
//     about 2.3× brighter (T = 3, 60°: ≈252 W/m², ≈31.5 klx, where clear skies
//     typically give 80–150 W/m², ≈10–20 klx); Preetham's absolute levels are
//     known to be off (Zotti, Wilkie & Purgathofer 2007 compare it with the CIE
//     skies). Kept for comparison with renderers that use it.
//
// The fit is undefined for a sun below the horizon: the shape uses the sun
// clamped to the horizon (same azimuth) and the level is multiplied by
// twilight_factor(sun elevation), so the sky fades to 0 at −18° without NaN.
#pragma once

#include "shading/sky/atmosphere.h"
#include "shading/sky/sky_model.h"

#include <glm/vec2.hpp>

namespace skylit::sky {

namespace preetham {

struct Perez {
  double A, B, C, D, E;
};
enum class Channel { Y, x, y };

Perez coefficients(Channel ch, double turbidity);
// F(θ, γ) for cos θ > 0; the limit (γ-part only) at cos θ = 0.
double perez(const Perez& p, double cos_theta, double gamma);
double zenith_luminance_kcd(double turbidity, double sun_zenith);
double zenith_chromaticity(Channel ch, double turbidity, double sun_zenith);  // ch = x or y

}  // namespace preetham

enum class PreethamLevel { Esra, Paper };

class PreethamSky final : public SkyModel {
 public:
  // sun_direction: unit vector toward the sun; turbidity in [1.7, 10].
  PreethamSky(const glm::dvec3& sun_direction, double turbidity, PreethamLevel level = PreethamLevel::Esra,
              double luminous_efficacy = kSkyLuminousEfficacy);
  Rgb radiance(const glm::dvec3& dir) const override;
  // Luminance (cd/m², twilight included) and chromaticity toward dir (dir.z > 0).
  double luminance_cd(const glm::dvec3& dir) const;
  glm::dvec2 chromaticity(const glm::dvec3& dir) const;
  double turbidity() const { return turbidity_; }
  const glm::dvec3& shape_sun() const { return shape_sun_; }

 private:
  // value of channel ch relative to its zenith value: F(θ,γ)/F(0,θs).
  double ratio(int ch, double cos_theta, double gamma) const;

  double turbidity_, efficacy_;
  glm::dvec3 shape_sun_;   // sun clamped to elevation ≥ 0
  double zenith_[3];       // broadband radiance (W m⁻² sr⁻¹, twilight included), x, y at the zenith
  preetham::Perez coef_[3];
  double denom_[3];        // F(0, θs) per channel
};

}  // namespace skylit::sky
