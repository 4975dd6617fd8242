#include "shading/sh_rotation.h"

#include <cmath>
#include <stdexcept>

namespace skylit::sh {

void rotate_z_inplace(std::span<double> c, double alpha) {
  const int order = order_of(c.size());
  for (int m = 1; m < order; ++m) {
    const double cm = std::cos(m * alpha), sm = std::sin(m * alpha);
    for (int l = m; l < order; ++l) {
      double& a = c[index(l, m)];   // cos(mφ) coefficient
      double& b = c[index(l, -m)];  // sin(mφ) coefficient
      const double na = a * cm - b * sm, nb = a * sm + b * cm;
      a = na;
      b = nb;
    }
  }
}

Vec rotate_z(std::span<const double> coeffs, double alpha) {
  Vec out(coeffs.begin(), coeffs.end());
  rotate_z_inplace(out, alpha);
  return out;
}

void add_rotated_zh(std::span<const double> zh, const glm::dvec3& axis, double scale, std::span<double> out) {
  const int order = order_of(out.size());
  if (zh.size() < static_cast<std::size_t>(order)) throw std::invalid_argument("add_rotated_zh: ZH too short");
  double y[64 * 4];
  if (order > 16) throw std::invalid_argument("add_rotated_zh: order too large");
  eval_basis(order, axis, std::span<double>(y, num_coeffs(order)));
  for (int l = 0; l < order; ++l) {
    const double k = scale * std::sqrt(4.0 * kPi / (2 * l + 1)) * zh[l];
    for (int m = -l; m <= l; ++m) out[index(l, m)] += k * y[index(l, m)];
  }
}

Vec rotate_zh(std::span<const double> zh, const glm::dvec3& axis) {
  Vec out(num_coeffs(static_cast<int>(zh.size())), 0.0);
  add_rotated_zh(zh, axis, 1.0, out);
  return out;
}

}  // namespace skylit::sh
