#include "shading/horizon/rhumb_rows.h"

#include <algorithm>
#include <cmath>

namespace skylit::horizon {
namespace {

// log1p(a)/a and expm1(b)/b, → 1 at 0; the series where the quotient would lose digits
// (|a| < 1e-5: the next term is below 1e-15).
double log1p_ratio(double a) { return std::abs(a) < 1e-5 ? 1.0 - a * (0.5 - a / 3.0) : std::log1p(a) / a; }
double expm1_ratio(double b) { return std::abs(b) < 1e-5 ? 1.0 + b * (0.5 + b / 6.0) : std::expm1(b) / b; }

}  // namespace

RhumbRows::RhumbRows(const terrain::HeightField& field)
    : dx_(field.dx_per_row), d_ref_(field.mean_dx()) {
  const int h = static_cast<int>(dx_.size());
  half_rows_.assign(std::max(1, 2 * (h - 1) + 1), 0.0);
  for (int j = 0; j + 1 < h; ++j) {
    const double beta = dx_[j + 1] - dx_[j];
    for (const int half : {1, 2}) {
      const double u = 0.5 * half;  // rows into the segment
      half_rows_[2 * j + half] = half_rows_[2 * j] + d_ref_ * (u / dx_[j]) * log1p_ratio(beta * u / dx_[j]);
    }
  }
}

double RhumbRows::dx(double y) const {
  const int h = static_cast<int>(dx_.size());
  const double yc = std::clamp(y, 0.0, h - 1.0);
  const int j0 = static_cast<int>(yc);
  const int j1 = std::min(j0 + 1, h - 1);
  const double a = yc - j0;
  return (1.0 - a) * dx_[j0] + a * dx_[j1];
}

double RhumbRows::gamma(double y) const {
  const int h = static_cast<int>(dx_.size());
  if (y <= 0.0) return y * d_ref_ / dx_[0];
  if (y >= h - 1.0) return last() + (y - (h - 1.0)) * d_ref_ / dx_[h - 1];
  const int j = std::min(static_cast<int>(y), h - 2);
  if (y == j) return half_rows_[2 * j];  // a whole row (the sweep's owners): the formula's value at u = 0
  const double u = y - j, beta = dx_[j + 1] - dx_[j];
  return half_rows_[2 * j] + d_ref_ * (u / dx_[j]) * log1p_ratio(beta * u / dx_[j]);
}

double RhumbRows::row(double g, int& segment) const {
  const int h = static_cast<int>(dx_.size());
  if (g <= 0.0 || h == 1) return g * dx_[0] / d_ref_;
  if (g >= last()) return (h - 1.0) + (g - last()) * dx_[h - 1] / d_ref_;
  segment = std::clamp(segment, 0, h - 2);
  while (segment < h - 2 && g >= half_rows_[2 * (segment + 1)]) ++segment;
  while (segment > 0 && g < half_rows_[2 * segment]) --segment;
  const double gg = (g - half_rows_[2 * segment]) / d_ref_;
  return segment + dx_[segment] * gg * expm1_ratio((dx_[segment + 1] - dx_[segment]) * gg);
}

}  // namespace skylit::horizon
