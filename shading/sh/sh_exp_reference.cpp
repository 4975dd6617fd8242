#include "shading/sh/sh_exp_reference.h"

#include "shading/sh/quadrature.h"
#include "shading/sh/sh_product.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace skylit::sh {
namespace {

// Cyclic Jacobi on a symmetric n×n row-major matrix: a becomes diagonal
// (eigenvalues), v the eigenvectors as columns (a_in = v·diag·vᵀ).
void jacobi_eigen(std::vector<double>& a, std::vector<double>& v, int n) {
  v.assign(static_cast<std::size_t>(n) * n, 0.0);
  for (int i = 0; i < n; ++i) v[i * n + i] = 1.0;
  double total = 0.0;
  for (double x : a) total += x * x;
  for (int sweep = 0; sweep < 100; ++sweep) {
    double off = 0.0;
    for (int p = 0; p < n; ++p)
      for (int q = p + 1; q < n; ++q) off += a[p * n + q] * a[p * n + q];
    if (off <= 1e-32 * total) return;
    for (int p = 0; p < n; ++p)
      for (int q = p + 1; q < n; ++q) {
        const double apq = a[p * n + q];
        if (apq == 0.0) continue;
        const double theta = (a[q * n + q] - a[p * n + p]) / (2.0 * apq);
        const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        for (int k = 0; k < n; ++k) {  // columns p, q: a·J
          const double kp = a[k * n + p], kq = a[k * n + q];
          a[k * n + p] = c * kp - s * kq;
          a[k * n + q] = s * kp + c * kq;
        }
        for (int k = 0; k < n; ++k) {  // rows p, q: Jᵀ·a
          const double pk = a[p * n + k], qk = a[q * n + k];
          a[p * n + k] = c * pk - s * qk;
          a[q * n + k] = s * pk + c * qk;
        }
        for (int k = 0; k < n; ++k) {
          const double kp = v[k * n + p], kq = v[k * n + q];
          v[k * n + p] = c * kp - s * kq;
          v[k * n + q] = s * kp + c * kq;
        }
      }
  }
}

}  // namespace

Vec exp_pointwise(std::span<const double> f, int nz, int nphi) {
  const int order = order_of(f.size());
  const int nc = num_coeffs(order);
  const auto rule = sh::sphere_product_rule(nz, nphi);
  const std::size_t nq = rule.dirs.size();
  std::vector<double> ys(nq * nc), vals(nq);
  double vmax = -std::numeric_limits<double>::infinity();
  for (std::size_t q = 0; q < nq; ++q) {
    const std::span<double> y(&ys[q * nc], nc);
    eval_basis(order, rule.dirs[q], y);
    double v = 0.0;
    for (int i = 1; i < nc; ++i) v += f[i] * y[i];
    vals[q] = v;
    vmax = std::max(vmax, v);
  }
  // exp* = e^{c + vmax}·P[e^{f̂ − vmax}]: no overflow before the final scale.
  Vec out(nc, 0.0);
  for (std::size_t q = 0; q < nq; ++q) {
    const double w = rule.weights[q] * std::exp(vals[q] - vmax);
    for (int i = 0; i < nc; ++i) out[i] += w * ys[q * nc + i];
  }
  const double scale = std::exp(f[0] / kSqrt4Pi + vmax);
  for (double& x : out) x *= scale;
  return out;
}

Vec exp_pointwise_zh(std::span<const double> zh, int nodes) {
  const int order = static_cast<int>(zh.size());
  const auto rule = sh::gauss_legendre(nodes);
  Vec out(order, 0.0), y(order);
  for (int q = 0; q < nodes; ++q) {
    const double z = rule.nodes[q];
    double v = 0.0;
    for (int l = 0; l < order; ++l) {
      y[l] = std::sqrt((2 * l + 1) / (4.0 * kPi)) * legendre(l, z);
      v += zh[l] * y[l];
    }
    const double w = 2.0 * kPi * rule.weights[q] * std::exp(v);
    for (int l = 0; l < order; ++l) out[l] += w * y[l];
  }
  return out;
}

Vec exp_product_algebra(std::span<const double> f) {
  const int order = order_of(f.size());
  const int nc = num_coeffs(order);
  Vec fhat(f.begin(), f.end());
  fhat[0] = 0.0;
  std::vector<double> a = triple_product(order).matrix(fhat), v;
  jacobi_eigen(a, v, nc);
  double lmax = -std::numeric_limits<double>::infinity();
  for (int j = 0; j < nc; ++j) lmax = std::max(lmax, a[j * nc + j]);
  // expm(M)·1 = V·e^Λ·Vᵀ·1 with 1 = √(4π)·e_0.
  Vec out(nc, 0.0);
  for (int j = 0; j < nc; ++j) {
    const double w = std::exp(a[j * nc + j] - lmax) * v[j] * kSqrt4Pi;  // v[0·nc + j]
    for (int i = 0; i < nc; ++i) out[i] += v[i * nc + j] * w;
  }
  const double scale = std::exp(f[0] / kSqrt4Pi + lmax);
  for (double& x : out) x *= scale;
  return out;
}

Vec log_product_algebra(std::span<const double> v, double floor) {
  const int order = order_of(v.size());
  const int nc = num_coeffs(order);
  std::vector<double> a = triple_product(order).matrix(v), e;
  jacobi_eigen(a, e, nc);
  // log(M)·1 = E·log Λ·Eᵀ·1 with 1 = √(4π)·e_0.
  Vec out(nc, 0.0);
  for (int j = 0; j < nc; ++j) {
    const double w = std::log(std::max(a[j * nc + j], floor)) * e[j] * kSqrt4Pi;  // e[0·nc + j]
    for (int i = 0; i < nc; ++i) out[i] += e[i * nc + j] * w;
  }
  return out;
}

}  // namespace skylit::sh
