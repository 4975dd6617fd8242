#include "shading/sh/sh_basis.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace skylit::sh {

double legendre(int l, double x) {
  if (l == 0) return 1.0;
  double p0 = 1.0, p1 = x;
  for (int k = 2; k <= l; ++k) {
    const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
    p0 = p1;
    p1 = p2;
  }
  return p1;
}

double assoc_legendre(int l, int m, double x) {
  // P_m^m = (−1)^m (2m−1)!! (1−x²)^{m/2}, then upward in l (stable recurrence).
  double pmm = 1.0;
  if (m > 0) {
    const double somx2 = std::sqrt(std::max(0.0, (1.0 - x) * (1.0 + x)));
    double fact = 1.0;
    for (int i = 1; i <= m; ++i) {
      pmm *= -fact * somx2;
      fact += 2.0;
    }
  }
  if (l == m) return pmm;
  double pmmp1 = x * (2 * m + 1) * pmm;
  if (l == m + 1) return pmmp1;
  double pll = 0.0;
  for (int ll = m + 2; ll <= l; ++ll) {
    pll = ((2 * ll - 1) * x * pmmp1 - (ll + m - 1) * pmm) / (ll - m);
    pmm = pmmp1;
    pmmp1 = pll;
  }
  return pll;
}

double sh_norm(int l, int m) {
  const int am = std::abs(m);
  double ratio = 1.0;  // (l−|m|)!/(l+|m|)!
  for (int k = l - am + 1; k <= l + am; ++k) ratio /= k;
  return std::sqrt((2 * l + 1) / (4.0 * kPi) * ratio);
}

double eval_basis_one(int l, int m, const glm::dvec3& d) {
  const double z = std::clamp(d.z, -1.0, 1.0);
  const double phi = std::atan2(d.y, d.x);
  const int am = std::abs(m);
  const double p = sh_norm(l, m) * assoc_legendre(l, am, z);
  if (m == 0) return p;
  return m > 0 ? std::sqrt(2.0) * p * std::cos(am * phi) : std::sqrt(2.0) * p * std::sin(am * phi);
}

namespace {

// K_lm = sh_norm(l, m), m ≥ 0, at [l(l+1)/2 + m], computed once: sh_norm's
// factorial-ratio loop and sqrt per coefficient and direction made eval_basis
// O(n³). Sized for reconstruct(), which takes orders up to 2·kMaxOrder; bands
// beyond it fall back to sh_norm. √2 is not folded in: eval_basis stays bitwise
// what the per-(l, m) sh_norm·assoc_legendre calls gave.
constexpr int kNormBands = 2 * kMaxOrder;
using NormTable = std::array<double, kNormBands * (kNormBands + 1) / 2>;

const NormTable& norm_table() {
  static const NormTable table = [] {
    NormTable t{};
    for (int l = 0; l < kNormBands; ++l)
      for (int m = 0; m <= l; ++m) t[l * (l + 1) / 2 + m] = sh_norm(l, m);
    return t;
  }();
  return table;
}

}  // namespace

void eval_basis(int order, const glm::dvec3& d, std::span<double> out) {
  if (out.size() < static_cast<std::size_t>(num_coeffs(order)))
    throw std::invalid_argument("eval_basis: output span too small");
  const double z = std::clamp(d.z, -1.0, 1.0);
  const double somx2 = std::sqrt(std::max(0.0, (1.0 - z) * (1.0 + z)));  // sin θ, as assoc_legendre has it
  const double rxy = std::hypot(d.x, d.y);
  // cos(mφ), sin(mφ) by the Chebyshev recurrence; φ undefined at the poles → 0.
  const double c1 = rxy > 0 ? d.x / rxy : 1.0, s1 = rxy > 0 ? d.y / rxy : 0.0;
  double cm = 1.0, sm = 0.0;
  const NormTable& norms = norm_table();
  double pmm = 1.0;  // P_m^m
  for (int m = 0; m < order; ++m) {
    // One pass per m with assoc_legendre's operations in its order, so the values
    // are bitwise the same: P_m^m = P_{m−1}^{m−1}·(−(2m−1) sin θ), P_{m+1}^m, then
    // upward in l.
    if (m > 0) pmm *= -(2.0 * m - 1.0) * somx2;
    double pl = pmm, pl_1 = 0.0;  // P_l^m, P_{l−1}^m
    for (int l = m; l < order; ++l) {
      if (l == m + 1) {
        pl_1 = pl;
        pl = z * (2 * m + 1) * pmm;
      } else if (l > m + 1) {
        const double next = ((2 * l - 1) * z * pl - (l + m - 1) * pl_1) / (l - m);
        pl_1 = pl;
        pl = next;
      }
      const double p = (l < kNormBands ? norms[l * (l + 1) / 2 + m] : sh_norm(l, m)) * pl;
      if (m == 0) {
        out[index(l, 0)] = p;
      } else {
        out[index(l, m)] = std::sqrt(2.0) * p * cm;
        out[index(l, -m)] = std::sqrt(2.0) * p * sm;
      }
    }
    const double cn = cm * c1 - sm * s1, sn = sm * c1 + cm * s1;
    cm = cn;
    sm = sn;
  }
}

Vec eval_basis(int order, const glm::dvec3& dir) {
  Vec out(num_coeffs(order));
  eval_basis(order, dir, out);
  return out;
}

double reconstruct(std::span<const double> coeffs, const glm::dvec3& dir) {
  const int order = order_of(coeffs.size());
  double y[kMaxOrder * kMaxOrder * 4];
  Vec big;
  std::span<double> ys(y, num_coeffs(order));
  if (order > kMaxOrder * 2) {
    big.resize(num_coeffs(order));
    ys = big;
  }
  eval_basis(order, dir, ys);
  return dot(coeffs, ys);
}

int order_of(std::size_t size) {
  const int n = static_cast<int>(std::lround(std::sqrt(static_cast<double>(size))));
  if (n < 1 || static_cast<std::size_t>(n * n) != size)
    throw std::invalid_argument("SH vector size " + std::to_string(size) + " is not a square");
  return n;
}

glm::dvec3 direction(double theta, double phi) {
  const double st = std::sin(theta);
  return {st * std::cos(phi), st * std::sin(phi), std::cos(theta)};
}

Vec constant_one(int order) {
  Vec v(num_coeffs(order), 0.0);
  v[0] = kSqrt4Pi;
  return v;
}

double dot(std::span<const double> a, std::span<const double> b) {
  if (a.size() != b.size()) throw std::invalid_argument("dot: size mismatch");
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

}  // namespace skylit::sh
