// CIE standard general sky (ISO 15469:2004 / CIE S 011/E:2003): relative
// luminance L/L_z = f(χ)·φ(Z) / (f(Z_s)·φ(0)) with the gradation
// φ(Z) = 1 + a·exp(b / cos Z) (φ = 1 at the horizon) and the indicatrix
// f(χ) = 1 + c·(exp(dχ) − exp(dπ/2)) + e·cos²χ, Z the zenith angle, χ the angle
// to the sun, Z_s the sun's zenith angle. Types 1..15 are the standard's table;
// type 16 is the traditional CIE overcast sky (Moon & Spencer 1942,
// L/L_z = (1 + 2 cos Z)/3), which type 1 approximates.
//
// Absolute level: the zenith radiance is an input (RGB, W m⁻² sr⁻¹; the
// standard defines only relative luminance and no colour, so a grey input
// gives a grey sky). `from_diffuse_horizontal` derives it from a diffuse
// horizontal irradiance D instead: L_z = D / ∫ (L/L_z) cos θ dω. A sun below
// the horizon is clamped to it for the shape; the level is not faded
// (the caller chooses it, e.g. with twilight_factor).
#pragma once

#include "shading/sky/sky_model.h"

namespace skylit::sky {

struct CieParams {
  double a, b, c, d, e;
};

inline constexpr int kCieTraditionalOvercast = 16;

// Gradation/indicatrix parameters of standard type 1..15; throws otherwise.
CieParams cie_standard_sky(int type);
double cie_gradation(const CieParams& p, double zenith_angle);      // φ(Z)
double cie_indicatrix(const CieParams& p, double scattering_angle);  // f(χ)
// L/L_z of type 1..16 for zenith angle Z, angle to the sun χ and sun zenith Z_s.
double cie_relative_luminance(int type, double Z, double chi, double Zs);

class CieSky final : public SkyModel {
 public:
  CieSky(int type, const glm::dvec3& sun_direction, const Rgb& zenith_radiance);
  // Zenith radiance chosen so the horizontal diffuse irradiance is `diffuse_horizontal` (W/m²).
  static CieSky from_diffuse_horizontal(int type, const glm::dvec3& sun_direction, const Rgb& diffuse_horizontal);

  Rgb radiance(const glm::dvec3& dir) const override;
  // Types 1, 3, 5 (indicatrix c = e = 0, so f ≡ 1) and 16 depend on Z only.
  bool azimuthally_symmetric() const override;
  double relative_luminance(const glm::dvec3& dir) const;  // L/L_z, 0 below the horizon
  // ∫ (L/L_z) cos θ dω over the sky (sr): D / L_z, by dense quadrature.
  double diffuse_horizontal_per_zenith() const;
  const Rgb& zenith_radiance() const { return zenith_; }

 private:
  int type_;
  glm::dvec3 shape_sun_;
  double sun_zenith_;
  Rgb zenith_;
};

}  // namespace skylit::sky
