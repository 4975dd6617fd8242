#include "shading/sh/sh_product.h"

#include "shading/sh/quadrature.h"

#include <array>
#include <cmath>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace skylit::sh {

TripleProduct::TripleProduct(int order) : order_(order) {
  if (order < 1 || order > kMaxOrder) throw std::invalid_argument("TripleProduct: order out of range");
  const int nc = num_coeffs(order);
  // Exact quadrature: the integrand has degree ≤ 3(order−1) in z and in φ.
  const auto rule = sh::sphere_rule_for_order(order);
  std::vector<double> ys(rule.dirs.size() * nc);
  for (std::size_t q = 0; q < rule.dirs.size(); ++q)
    eval_basis(order, rule.dirs[q], std::span<double>(&ys[q * nc], nc));
  for (int i = 0; i < nc; ++i)
    for (int j = 0; j < nc; ++j)
      for (int k = 0; k < nc; ++k) {
        double s = 0.0;
        for (std::size_t q = 0; q < rule.dirs.size(); ++q) {
          const double* y = &ys[q * nc];
          s += rule.weights[q] * y[i] * y[j] * y[k];
        }
        if (std::abs(s) > 1e-12) entries_.push_back({i, j, k, s});
      }
}

void TripleProduct::product(std::span<const double> f, std::span<const double> g, std::span<double> out) const {
  const std::size_t nc = static_cast<std::size_t>(num_coeffs(order_));
  if (f.size() != nc || g.size() != nc || out.size() != nc)
    throw std::invalid_argument("TripleProduct::product: size mismatch");
  std::fill(out.begin(), out.end(), 0.0);
  for (const auto& e : entries_) out[e.i] += e.value * f[e.j] * g[e.k];
}

Vec TripleProduct::product(std::span<const double> f, std::span<const double> g) const {
  Vec out(num_coeffs(order_));
  product(f, g, out);
  return out;
}

std::vector<double> TripleProduct::matrix(std::span<const double> f) const {
  const int nc = num_coeffs(order_);
  std::vector<double> m(static_cast<std::size_t>(nc) * nc, 0.0);
  for (const auto& e : entries_) m[static_cast<std::size_t>(e.i) * nc + e.j] += e.value * f[e.k];
  return m;
}

const TripleProduct& triple_product(int order) {
  static std::array<std::unique_ptr<TripleProduct>, kMaxOrder + 1> cache;
  static std::mutex mutex;
  if (order < 1 || order > kMaxOrder) throw std::invalid_argument("triple_product: order out of range");
  std::lock_guard lock(mutex);
  if (!cache[order]) cache[order] = std::make_unique<TripleProduct>(order);
  return *cache[order];
}

}  // namespace skylit::sh
