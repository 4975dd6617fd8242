// Azimuth conventions, in one place (DESIGN.md "Conventions", math-notes §0).
// Products and the CLI speak geographic azimuth A (from north, clockwise); the math
// frame (x east, y north, z up) measures φ from +x toward +y: φ = π/2 − A.
// Product band k of W has A_k = k·2π/W.
#pragma once

#include <cmath>
#include <numbers>

namespace skylit::horizon {

inline constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Math-frame azimuth φ of a geographic azimuth A (radians), and back.
inline double math_from_geographic(double geographic) { return std::numbers::pi / 2 - geographic; }
inline double geographic_from_math(double phi) { return std::numbers::pi / 2 - phi; }

// Geographic azimuth of product band k of W (radians).
inline double band_azimuth(int k, int azimuths) { return kTwoPi * k / azimuths; }

// Horizontal unit direction (east, north) of a geographic azimuth.
struct Heading {
  double east = 0.0;
  double north = 1.0;
};
// sin/cos leave ~1e−16 where the exact component is 0 (N, E, S, W); snapping it
// keeps rays along the grid's edge rows/columns on the grid.
inline double snap_to_zero(double v) { return std::abs(v) < 1e-12 ? 0.0 : v; }
inline Heading heading_from_geographic(double geographic) {
  return {snap_to_zero(std::sin(geographic)), snap_to_zero(std::cos(geographic))};
}
inline Heading heading_from_math(double phi) { return {snap_to_zero(std::cos(phi)), snap_to_zero(std::sin(phi))}; }
// The angle between two headings (radians, 0 … π).
inline double heading_angle(Heading a, Heading b) {
  return std::abs(std::atan2(a.east * b.north - a.north * b.east, a.east * b.east + a.north * b.north));
}

}  // namespace skylit::horizon
