// The sun as a key light, and the photometric/colour conversions the sky
// models share. Units and RGB convention: sky_model.h.
//
// Direct beam (and the clear-sky diffuse level): broadband direct normal irradiance (DNI) from the ESRA clear-sky
// model (Rigollier, Bauer & Wald 2000): DNI = E0·exp(−0.8662·T_L·m·δ_R(m)),
// with m the Kasten–Young (1989) relative optical air mass, δ_R Kasten's (1996)
// Rayleigh optical thickness and T_L the Linke turbidity (air mass 2). We use
// the sky turbidity T for T_L: both are total over clean-dry-air extinction
// (an approximation; Preetham's T is defined at 550 nm). Colour: per-channel
// transmittance exp(−m·(τ_Rayleigh(λ) + τ_aerosol(λ))), Rayleigh after Leckner
// (1978), aerosol by Ångström with Preetham's β(T) = 0.04608 T − 0.04586 and
// α = 1.3, rescaled so that the luminance of the RGB DNI equals the broadband
// DNI. Ozone, water vapour and mixed-gas absorption are not coloured.
#pragma once

#include "shading/sh/sh_basis.h"
#include "shading/sky/sky_model.h"

#include <glm/vec3.hpp>

namespace skylit::sky {

// Total solar irradiance at 1 AU, W/m² (Kopp & Lean 2011).
inline constexpr double kSolarConstant = 1361.0;
// Mean angular radius of the solar disc (959.63″), radians.
inline constexpr double kSunAngularRadius = 0.26656 * sh::kPi / 180.0;
// Luminous efficacy of clear/overcast sky diffuse light, lm/W (typical of the
// measured 110–140 lm/W range, e.g. Littlefair 1985; Perez et al. 1990):
// converts a sky luminance (cd/m²) to broadband radiance (W m⁻² sr⁻¹).
inline constexpr double kSkyLuminousEfficacy = 125.0;
// Representative channel wavelengths (µm) for the sun's colour (as in
// Bruneton's precomputed-scattering demo: 680, 550, 440 nm).
inline constexpr glm::dvec3 kChannelWavelengths{0.680, 0.550, 0.440};

// Kasten & Young (1989) relative optical air mass for a solar elevation (rad);
// +∞ for elevations below 0 (no direct beam is modelled there).
double kasten_young_air_mass(double elevation);
// Kasten (1996) Rayleigh optical thickness of the whole atmosphere at air mass m.
double kasten_rayleigh_thickness(double air_mass);
// Ångström turbidity coefficient β for Preetham's turbidity T.
double angstrom_beta(double turbidity);
// Spectral vertical optical depths at wavelength λ (µm), sea level.
double rayleigh_optical_depth(double lambda_um);
double aerosol_optical_depth(double lambda_um, double turbidity);

// ESRA clear-sky diffuse horizontal irradiance (W/m², Rigollier et al. 2000
// eqs. 23–28): E0·T_rd(T_L)·F_d(T_L, sin h), with the sun elevation h clamped
// to ≥ 0 (the caller fades it below the horizon).
double esra_diffuse_horizontal(double elevation, double turbidity);

// Broadband DNI (W/m²); 0 when the sun's centre is below the horizon.
double broadband_dni(double elevation, double turbidity);
// RGB DNI (W/m²), luminance(dni) == broadband_dni.
Rgb direct_normal_irradiance(double elevation, double turbidity);

struct Sun {
  glm::dvec3 direction{0.0, 0.0, 1.0};  // unit, toward the sun (z up, x east, y north)
  Rgb dni{0.0};                          // W/m² on a plane normal to the beam
  // Solid angle of the disc and its (uniform, no limb darkening) radiance.
  static double solid_angle();
  Rgb disc_radiance() const;
};

// Sun for a unit direction and turbidity (validated like the sky: 1.7..10).
Sun make_sun(const glm::dvec3& direction, double turbidity);

// CIE xyY (Y in any photometric unit) → linear sRGB in the same unit, with
// negative (out-of-gamut) channels clamped to 0.
Rgb xyY_to_linear_srgb(double x, double y, double Y);

// Throws std::invalid_argument outside the turbidity range the fits support.
inline constexpr double kMinTurbidity = 1.7;
inline constexpr double kMaxTurbidity = 10.0;
void check_turbidity(double turbidity);

}  // namespace skylit::sky
