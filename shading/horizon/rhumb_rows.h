// Rays of one heading on a grid whose rows have different east–west spacings
// (geographic DEMs), for the sweep: they are rhumb lines, and in a stretched row
// coordinate Γ they are straight, so one heading's rays are translates of each other.
//
// With D(y) the east–west spacing at fractional row y (linear between rows and constant
// beyond the edges, as horizon_ray.h's dx_at_row) and heading (east e, north n), a ray
// moves dx/dy = −(e·dy)/(n·D(y)) texels. With Γ(y) = D_ref·∫₀^y dy'/D(y') that reads
//   x = c + r·Γ(y),  r = −e·dy/(n·D_ref),   or, solved for Γ,  Γ(y) = c + r·x, r = −n·D_ref/(e·dy):
// straight lines in (x, Γ) with one slope r per heading; on a grid of one spacing Γ = y
// and these are the projected sweep's lines. Per row segment j, D = D_j + β_j·(y − j):
//   Γ(y) − Γ(j) = D_ref·((y − j)/D_j)·log1p(a)/a,   a = β_j·(y − j)/D_j,
//   y − j = D_j·g·expm1(b)/b,  g = (Γ − Γ(j))/D_ref,  b = β_j·g   (the inverse),
// both well conditioned for β → 0 (the ratios → 1). The exact march's chord
// (ray_point: dx at the ray's mid-row) departs from this curve by second order in the
// change of D along the ray: ≈ 0.1 texel over 1200 texels at 60° N (docs/accuracy.md).
#pragma once

#include "terrain/height_field.h"

#include <vector>

namespace skylit::horizon {

class RhumbRows {
 public:
  explicit RhumbRows(const terrain::HeightField& field);

  double d_ref() const { return d_ref_; }  // m: the mean east–west spacing
  // Γ at fractional row y.
  double gamma(double y) const;
  // The row y with Γ(y) = g; `segment` is a row hint, updated (walks are monotone).
  double row(double g, int& segment) const;
  // East–west spacing (m) at fractional row y, as dx_at_row.
  double dx(double y) const;
  // Γ of every half row, Γ(k/2) for k = 0 … 2(H − 1): the sweep's sample rows and its
  // owners' rows, in double for the GPU's twin.
  const std::vector<double>& half_rows() const { return half_rows_; }
  double last() const { return half_rows_.back(); }  // Γ(H − 1)

 private:
  std::vector<double> dx_;          // per row (m)
  std::vector<double> half_rows_;   // Γ(k/2)
  double d_ref_ = 1.0;
};

}  // namespace skylit::horizon
