// Where a horizon ray goes on the grid: level-0 texel coordinates of the point at
// ground distance t (m) from texel (i, j) along a heading, plus plain bilinear heights.
// Shared by the multi-resolution march and the exact march so both see the same
// geometry (terrain/pyramid.h coordinate convention: x east = column, y south = row).
#pragma once

#include "shading/horizon/azimuth.h"
#include "terrain/height_field.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace skylit::horizon {

// East–west spacing (m) at fractional row y, linear between rows, clamped.
inline double dx_at_row(const terrain::HeightField& f, double y) {
  const double yc = std::clamp(y, 0.0, static_cast<double>(f.height - 1));
  const int j0 = static_cast<int>(yc);
  const int j1 = std::min(j0 + 1, f.height - 1);
  const double a = yc - j0;
  return (1.0 - a) * f.dx(j0) + a * f.dx(j1);
}

struct GridPoint {
  double x = 0.0, y = 0.0;
};

// For geographic DEMs dx varies by row: the east offset uses dx at the ray's
// mid-row, which keeps the metric length of the offset within O((Δdx)²).
// From any point of the grid (fractional texels): offset marching starts above one.
inline GridPoint ray_point(const terrain::HeightField& f, GridPoint origin, Heading u, double t) {
  const double y = origin.y - t * u.north / f.dy;
  const double x = origin.x + t * u.east / dx_at_row(f, 0.5 * (origin.y + y));
  return {x, y};
}
inline GridPoint ray_point(const terrain::HeightField& f, int i, int j, Heading u, double t) {
  return ray_point(f, GridPoint{static_cast<double>(i), static_cast<double>(j)}, u, t);
}

// Tolerance (texels) for a sample on the grid's last row/column: a few float ulps of
// the largest coordinate, so rounding (double here, float on the GPU, which uses the
// same value) never decides whether an edge sample counts.
inline double edge_epsilon_texels(const terrain::HeightField& f) {
  return 1e-6 * std::max(f.width, f.height) + 1e-5;
}

// Inside the span of texel centres (within the edge tolerance); bilinear_height
// clamps the few samples that sit within the tolerance outside it.
inline bool on_grid(const terrain::HeightField& f, GridPoint p) {
  const double e = edge_epsilon_texels(f);
  return p.x >= -e && p.y >= -e && p.x <= f.width - 1 + e && p.y <= f.height - 1 + e;
}

// Bilinear height at a point on the grid (filled heights under nodata).
inline double bilinear_height(const terrain::HeightField& f, GridPoint p) {
  p.x = std::clamp(p.x, 0.0, static_cast<double>(f.width - 1));
  p.y = std::clamp(p.y, 0.0, static_cast<double>(f.height - 1));
  const int i0 = std::min(static_cast<int>(p.x), f.width - 2 < 0 ? 0 : f.width - 2);
  const int j0 = std::min(static_cast<int>(p.y), f.height - 2 < 0 ? 0 : f.height - 2);
  const int i1 = std::min(i0 + 1, f.width - 1), j1 = std::min(j0 + 1, f.height - 1);
  const double a = p.x - i0, b = p.y - j0;
  const double top = (1.0 - a) * f.at(i0, j0) + a * f.at(i1, j0);
  const double bottom = (1.0 - a) * f.at(i0, j1) + a * f.at(i1, j1);
  return (1.0 - b) * top + b * bottom;
}

// Whether every row has the same east–west spacing (projected grids): the sweep's
// condition, and the march kernel's uniform-spacing variant's.
inline bool one_row_spacing(const terrain::HeightField& f) {
  return !f.dx_per_row.empty() &&
         std::adjacent_find(f.dx_per_row.begin(), f.dx_per_row.end(), std::not_equal_to<>()) == f.dx_per_row.end();
}

// Smallest texel side (m): the march's length unit.
inline double min_texel_size(const terrain::HeightField& f) {
  return std::min(f.dy, *std::min_element(f.dx_per_row.begin(), f.dx_per_row.end()));
}

// The DEM's extent (diagonal, m): the default maximum marching distance.
inline double dem_extent(const terrain::HeightField& f) {
  return std::hypot(f.width * f.mean_dx(), f.height * f.dy);
}

}  // namespace skylit::horizon
