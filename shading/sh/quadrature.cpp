#include "shading/sh/quadrature.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace skylit::sh {

namespace {

// P_n(x) and P_n'(x) by the three-term recurrence.
std::pair<double, double> legendre_with_derivative(int n, double x) {
  double p0 = 1.0, p1 = x;
  for (int k = 2; k <= n; ++k) {
    const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
    p0 = p1;
    p1 = p2;
  }
  if (n == 1) p0 = 1.0;
  return {p1, n * (x * p1 - p0) / (x * x - 1.0)};
}

}  // namespace

Rule1D gauss_legendre(int n, double a, double b) {
  if (n < 1) throw std::invalid_argument("gauss_legendre: n must be ≥ 1");
  Rule1D r;
  r.nodes.resize(n);
  r.weights.resize(n);
  const double half = 0.5 * (b - a), mid = 0.5 * (b + a);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double x = std::cos(sh::kPi * (i + 0.75) / (n + 0.5));  // Newton from Tricomi's guess
    for (int it = 0; it < 100; ++it) {
      const auto [p, dp] = legendre_with_derivative(n, x);
      const double dx = p / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    const double dp = legendre_with_derivative(n, x).second;
    const double w = 2.0 / ((1.0 - x * x) * dp * dp);
    r.nodes[i] = mid - half * x;
    r.nodes[n - 1 - i] = mid + half * x;
    r.weights[i] = r.weights[n - 1 - i] = half * w;
  }
  return r;
}

SphereRule sphere_product_rule(int nz, int nphi, double z_min, double z_max) {
  if (nphi < 1) throw std::invalid_argument("sphere_product_rule: nphi must be ≥ 1");
  const Rule1D gz = gauss_legendre(nz, z_min, z_max);
  SphereRule s;
  s.dirs.reserve(static_cast<std::size_t>(nz) * nphi);
  s.weights.reserve(s.dirs.capacity());
  const double dphi = 2.0 * sh::kPi / nphi;
  for (int i = 0; i < nz; ++i) {
    const double z = gz.nodes[i], r = std::sqrt(std::max(0.0, 1.0 - z * z));
    for (int j = 0; j < nphi; ++j) {
      const double phi = (j + 0.5) * dphi;
      s.dirs.push_back({r * std::cos(phi), r * std::sin(phi), z});
      s.weights.push_back(gz.weights[i] * dphi);
    }
  }
  return s;
}

SphereRule sphere_rule_for_order(int order) {
  // Triple products have degree ≤ 3(order−1) in z and in φ.
  const int deg = 3 * (order - 1);
  return sphere_product_rule(deg / 2 + 1, deg + 1);
}

sh::Vec project(int order, const SphereRule& rule, const std::function<double(const glm::dvec3&)>& f) {
  sh::Vec out(sh::num_coeffs(order), 0.0), y(out.size());
  for (std::size_t k = 0; k < rule.dirs.size(); ++k) {
    const double w = rule.weights[k] * f(rule.dirs[k]);
    if (w == 0.0) continue;
    sh::eval_basis(order, rule.dirs[k], y);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] += w * y[i];
  }
  return out;
}

sh::Vec project_smooth(int order, const std::function<double(const glm::dvec3&)>& f, int nz, int nphi) {
  return project(order, sphere_product_rule(nz, nphi), f);
}

}  // namespace skylit::sh
