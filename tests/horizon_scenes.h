// Analytic scenes for the horizon and product tests, with the closed forms they are
// checked against (derived in the comments; no marching involved).
#pragma once

#include "terrain/height_field.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace skylit::test {

inline terrain::HeightField make_field(int w, int h, double dx) { return terrain::HeightField(w, h, dx); }

// Plane rising toward the east with slope tan(s) (s in radians).
inline terrain::HeightField tilted_plane(int n, double dx, double s) {
  auto f = make_field(n, n, dx);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) f.at(i, j) = static_cast<float>(std::tan(s) * i * dx);
  return f;
}

// Radial pit around the centre texel: floor −depth for r ≤ r0, a raised-cosine wall up
// to 0 at r1, flat 0 beyond. Smooth, so bilinear interpolation errs by ≤ h''·dx²/8.
inline double pit_profile(double r, double r0, double r1, double depth) {
  if (r <= r0) return -depth;
  if (r >= r1) return 0.0;
  return -depth * 0.5 * (1.0 + std::cos(std::numbers::pi * (r - r0) / (r1 - r0)));
}
inline terrain::HeightField radial_pit(int n, double dx, double r0, double r1, double depth) {
  auto f = make_field(n, n, dx);
  const int c = n / 2;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      f.at(i, j) = static_cast<float>(pit_profile(std::hypot(i - c, j - c) * dx, r0, r1, depth));
  return f;
}
// Rim elevation γ seen from the pit's centre: max over t of atan((h(t) + depth)/t),
// by a dense 1-D search along the profile (t ≤ t_max).
inline double pit_rim_elevation(double r0, double r1, double depth, double t_max) {
  double best = -1.0;
  for (double t = 1e-3; t <= t_max; t += 1e-3)
    best = std::max(best, std::atan((pit_profile(t, r0, r1, depth) + depth) / t));
  return best;
}

// A north–south wall: texel columns [col0, col0 + thick) raised to `height` on rows
// [c − half_rows, c + half_rows], c the centre row. A receiver at row c, D metres east
// of the wall's east face (the top corner x of the last raised column), sees the wall
// at elevation atan(H·|cos ψ|/D) for |ψ| ≤ ψ_L (ψ from due west, tan ψ_L = L/D, L the
// half-length to the end rows' centres) — exact for bilinear heights: the ramp below the
// face top is linear, so along any ray the steepest point is the face top.
inline terrain::HeightField wall(int n, double dx, int col0, int thick, int half_rows, double height) {
  auto f = make_field(n, n, dx);
  const int c = n / 2;
  for (int j = c - half_rows; j <= c + half_rows; ++j)
    for (int i = col0; i < col0 + thick; ++i) f.at(i, j) = static_cast<float>(height);
  return f;
}
// Closed forms for the wall, n = z, sky above the horizontal (a = H/D):
//  skyview = (1/2π)[2π − 2ψ_L + (2/√(1+a²))·atan(tan ψ_L/√(1+a²))]
//    (∫ cos²σ dψ/(2π) with cos²σ = 1/(1 + a²cos²ψ); ψ_L = π/2 gives (1 + cos γ)/2)
//  svf     = 1 − asin(sin γ · sin ψ_L)/π,   γ = atan(a)
//    (∫ sin σ dψ = ∫ a cos ψ/√(1 + a² cos² ψ) dψ = asin(a sin ψ/√(1+a²)))
inline double wall_skyview(double a, double psi_l) {
  const double r = std::sqrt(1.0 + a * a);
  return (2 * std::numbers::pi - 2 * psi_l + 2 / r * std::atan(std::tan(psi_l) / r)) / (2 * std::numbers::pi);
}
inline double wall_svf(double a, double psi_l) {
  return 1.0 - std::asin(std::sin(std::atan(a)) * std::sin(psi_l)) / std::numbers::pi;
}

}  // namespace skylit::test
