#include "shading/sh/sh_rotation.h"

#include "shading/sh/quadrature.h"

#include <glm/matrix.hpp>

#include <algorithm>
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

double zh_rotation_factor(int l) { return std::sqrt(4.0 * kPi / (2 * l + 1)); }

void add_rotated_zh(std::span<const double> zh, const glm::dvec3& axis, double scale, std::span<double> out) {
  const int order = order_of(out.size());
  if (zh.size() < static_cast<std::size_t>(order)) throw std::invalid_argument("add_rotated_zh: ZH too short");
  double y[64 * 4];
  if (order > 16) throw std::invalid_argument("add_rotated_zh: order too large");
  eval_basis(order, axis, std::span<double>(y, num_coeffs(order)));
  for (int l = 0; l < order; ++l) {
    const double k = scale * zh_rotation_factor(l) * zh[l];
    for (int m = -l; m <= l; ++m) out[index(l, m)] += k * y[index(l, m)];
  }
}

Vec rotate_zh(std::span<const double> zh, const glm::dvec3& axis) {
  Vec out(num_coeffs(static_cast<int>(zh.size())), 0.0);
  add_rotated_zh(zh, axis, 1.0, out);
  return out;
}

namespace {

// Product rules exact for the degree-2(n−1) integrands of band n−1, one per order.
const sh::SphereRule& rotation_rule(int order) {
  static const std::array<sh::SphereRule, kMaxOrder + 1> rules = [] {
    std::array<sh::SphereRule, kMaxOrder + 1> r;
    for (int n = 1; n <= kMaxOrder; ++n) r[n] = sh::sphere_product_rule(n, 2 * n - 1);
    return r;
  }();
  return rules[order];
}

}  // namespace

ShRotation::ShRotation(int order, const glm::dmat3& rotation) : order_(order) {
  if (order < kMinOrder || order > kMaxOrder) throw std::invalid_argument("ShRotation: order out of range");
  const glm::dmat3 rt = glm::transpose(rotation);
  const glm::dmat3 gram = rt * rotation;
  double dev = std::abs(glm::determinant(rotation) - 1.0);
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) dev = std::max(dev, std::abs(gram[c][r] - (c == r ? 1.0 : 0.0)));
  if (dev > 1e-6) throw std::invalid_argument("ShRotation: matrix is not a proper rotation");

  const auto& rule = rotation_rule(order);
  const int nc = num_coeffs(order);
  std::array<double, kMaxOrder * kMaxOrder> y{}, y_rot{};
  for (std::size_t q = 0; q < rule.dirs.size(); ++q) {
    eval_basis(order, rule.dirs[q], std::span<double>(y.data(), nc));
    eval_basis(order, rt * rule.dirs[q], std::span<double>(y_rot.data(), nc));
    for (int l = 0; l < order; ++l) {
      double* block = &blocks_[rotation_band_offset(l)];
      const int w = 2 * l + 1, base = index(l, -l);
      for (int r = 0; r < w; ++r)
        for (int c = 0; c < w; ++c) block[r * w + c] += rule.weights[q] * y[base + r] * y_rot[base + c];
    }
  }
}

std::span<const double> ShRotation::band(int l) const {
  if (l < 0 || l >= order_) throw std::out_of_range("ShRotation::band: band out of range");
  const auto size = static_cast<std::size_t>((2 * l + 1) * (2 * l + 1));
  return std::span<const double>(&blocks_[rotation_band_offset(l)], size);
}

void ShRotation::apply(std::span<const double> in, std::span<double> out) const {
  const std::size_t nc = static_cast<std::size_t>(num_coeffs(order_));
  if (in.size() != nc || out.size() != nc) throw std::invalid_argument("ShRotation::apply: size mismatch");
  std::array<double, 2 * kMaxOrder - 1> band_in{};  // copy so that in and out may alias
  for (int l = 0; l < order_; ++l) {
    const int w = 2 * l + 1, base = index(l, -l);
    std::copy_n(in.begin() + base, w, band_in.begin());
    const double* block = &blocks_[rotation_band_offset(l)];
    for (int r = 0; r < w; ++r) {
      double acc = 0.0;
      for (int c = 0; c < w; ++c) acc += block[r * w + c] * band_in[c];
      out[base + r] = acc;
    }
  }
}

Vec ShRotation::apply(std::span<const double> in) const {
  Vec out(in.size());
  apply(in, out);
  return out;
}

Vec rotate(std::span<const double> coeffs, const glm::dmat3& rotation) {
  return ShRotation(order_of(coeffs.size()), rotation).apply(coeffs);
}

}  // namespace skylit::sh
