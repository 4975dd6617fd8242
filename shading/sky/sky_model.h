// Sky radiance models: the interface every sky implements, the frame, and the
// uniform sky. Units and colour (stated once, here, for all sky_* files):
//   * RGB = linear sRGB (Rec. 709 primaries, D65 white).
//   * The Rec. 709 luminance-weighted sum 0.2126 R + 0.7152 G + 0.0722 B of a
//     radiance is the broadband (solar-spectrum) radiance in W m⁻² sr⁻¹; grey
//     (1,1,1)·L is L W m⁻² sr⁻¹. Luminance-based models divide cd/m² by a
//     stated luminous efficacy (atmosphere.h) to get there.
//   * Frame: z up, x east, y north. Geographic azimuth A (from north,
//     clockwise) maps to the math azimuth φ = π/2 − A (math-notes §0).
//   * Sky radiance is 0 for directions with z ≤ 0: the ground is handled
//     elsewhere (terrain visibility, albedo). The solar disc is never part of
//     a sky model; the sun is the separate key light (atmosphere.h).
#pragma once

#include <glm/vec3.hpp>

namespace skylit::sky {

using Rgb = glm::dvec3;

struct SkyModel {
  virtual ~SkyModel() = default;
  // RGB radiance (W m⁻² sr⁻¹) arriving from unit direction `dir`; 0 if dir.z ≤ 0.
  virtual Rgb radiance(const glm::dvec3& dir) const = 0;
  // True only if radiance(Rz·dir) = radiance(dir) for every rotation Rz about z
  // (declared, for the sky×BRDF table's rotation shortcut, sky_brdf_table.h).
  virtual bool azimuthally_symmetric() const { return false; }
};

// Rec. 709 luminance weights: the broadband scalar of an RGB quantity.
double luminance(const Rgb& c);

// Unit direction from geographic azimuth (rad, from north, clockwise) and
// elevation (rad above the horizontal).
glm::dvec3 direction_from_azimuth_elevation(double azimuth, double elevation);
// Geographic azimuth in [0, 2π) and elevation of a unit direction.
double azimuth_of(const glm::dvec3& dir);
double elevation_of(const glm::dvec3& dir);
// The angle (rad, [0, π]) between two directions, accurate for small angles too.
double angle_between(const glm::dvec3& a, const glm::dvec3& b);

// Sky brightness factor for a sun below the horizon (1 for elevation ≥ 0).
// Measured horizontal illuminance falls about 0.4 decades per degree of solar
// depression (≈400 lx at sunset, ≈3 lx at −6°, ≈0.008 lx at −12°, e.g. the
// USNO/Schlyter twilight tables), so f = 10^(0.4·e_deg), and exactly 0 below
// −18° (astronomical night: starlight and airglow are out of scope).
double twilight_factor(double sun_elevation);

// Constant radiance over the upper hemisphere.
class UniformSky final : public SkyModel {
 public:
  explicit UniformSky(const Rgb& radiance = Rgb(1.0));
  Rgb radiance(const glm::dvec3& dir) const override;
  bool azimuthally_symmetric() const override { return true; }

 private:
  Rgb radiance_;
};

}  // namespace skylit::sky
