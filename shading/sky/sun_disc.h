// Visible fraction of a key light above a terrain horizon (DESIGN.md pipeline step 8;
// NS09 supplemental §1 "key-light restriction in elevation").
//
// Solar disc. The disc (angular radius r, 0.26656° for the sun) is tiny, so it is
// treated in its own tangent plane: x along increasing geographic azimuth, y along
// increasing elevation, both in units of r; the disc is the unit disc. A horizon that
// is locally straight across it, e = σ + k·(A − A_s), becomes the line
//   y = (σ − e_s)/r + m·x,   m = k / cos e_s
// (an azimuth step dA is an angle cos e_s·dA at elevation e_s). Its signed distance
// from the centre, (e_s − σ)/(r·√(1+m²)) = u, gives the visible fraction in closed
// form from the circular segment: 1 − (acos u − u·√(1−u²))/π. The tangent plane of
// the surface is a great circle, i.e. exactly a straight line in this frame, at
// angular distance asin(n·s) from the sun. Several lines, or a piecewise-linear
// horizon, are integrated exactly by clipping a polygon and intersecting it with the
// disc (Green's theorem, allocation-free). The tangent-plane frame errs by O(r²).
// Near the zenith (disc within r of it) azimuth is degenerate: cos e_s is held at
// sin r, the value where the disc spans ±90° of azimuth.
//
// Rectangular key light (NS09 key lights restricted in azimuth and elevation):
// fraction of its solid angle ∫∫ cos e de dA above a linear or piecewise-linear
// horizon, in closed form.
#pragma once

#include "shading/sky/atmosphere.h"

#include <glm/vec3.hpp>

#include <span>

namespace skylit::sky {

// Visible side {(x, y) : nx·x + ny·y + offset > 0} in the disc frame (units of r);
// (nx, ny) unit. offset > 0: the disc's centre is visible.
struct DiscLine {
  double nx = 0.0;
  double ny = 1.0;
  double offset = 0.0;
};

// Most lines / polyline vertices the exact routines accept (fixed-size work arrays).
inline constexpr int kMaxDiscLines = 8;
inline constexpr int kMaxPolylinePoints = 65;

// Closed form: fraction of the unit disc on the visible side of a line at signed
// distance u (clamped to [−1, 1]).
double disc_fraction_above_line(double u);

// Exact fraction of the unit disc on the visible side of every line (≤ kMaxDiscLines).
double disc_fraction_above_lines(std::span<const DiscLine> lines);

// Exact fraction of the unit disc above the piecewise-linear horizon through (x_k, y_k)
// (x ascending, x_0 ≤ −1 and x_last ≥ 1, ≤ kMaxPolylinePoints points) and on the
// visible side of `extra` (e.g. the tangent plane) when given.
double disc_fraction_above_polyline(std::span<const double> x, std::span<const double> y,
                                    const DiscLine* extra = nullptr);

// cos e_s, floored at sin r near the zenith (see above): the angle one radian of
// azimuth spans at the sun's elevation.
double disc_azimuth_scale(double sun_elevation, double radius);

// The horizon e = σ + slope·(A − A_s) as a line in the disc frame (radians in).
DiscLine horizon_line(double sun_elevation, double sigma, double slope, double radius = sky::kSunAngularRadius);

// The surface's tangent plane (unit normal, east-north-up) as a line in the disc frame
// of a sun at geographic azimuth A_s and elevation e_s.
DiscLine tangent_plane_line(const glm::dvec3& normal, double sun_azimuth, double sun_elevation,
                            double radius = sky::kSunAngularRadius);

// Fraction of the solar disc centred at elevation e_s visible above a horizon of
// elevation σ and slope dσ/dA at the sun's azimuth (closed form). 0: full shadow.
double sun_disc_fraction(double sun_elevation, double sigma, double slope = 0.0,
                         double radius = sky::kSunAngularRadius);

// Rectangular key light: geographic azimuths [azimuth_min, azimuth_max] (width ≤ 2π),
// elevations [elevation_min, elevation_max] ⊂ [−π/2, π/2], radians.
struct RectLight {
  double azimuth_min = 0.0;
  double azimuth_max = 0.0;
  double elevation_min = 0.0;
  double elevation_max = 0.0;
};

// Throws std::invalid_argument for an empty or inverted rectangle.
void validate(const RectLight& light);

// Fraction of the light's solid angle above e = σ_c + slope·(A − A_c), A_c its centre
// azimuth (closed form).
double rect_light_fraction(const RectLight& light, double sigma_centre, double slope = 0.0);

// Same above the piecewise-linear horizon through (azimuth_k, σ_k) (ascending,
// covering the light's azimuths; constant beyond the end samples).
double rect_light_fraction(const RectLight& light, std::span<const double> azimuths, std::span<const double> sigma);

}  // namespace skylit::sky
