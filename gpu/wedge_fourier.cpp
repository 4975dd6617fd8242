#include "gpu/wedge_fourier.h"

#include "shading/sh/sh_basis.h"

#include <algorithm>
#include <cmath>

namespace skylit::gpu {

namespace {
// Far below float32's 6e-8, far above double rounding of G's sums.
constexpr double kResidue = 1e-13;
}  // namespace

// With k = j + first_tap + s (mod W), φ_j = φ_k − d_s, d_s = (first_tap + s)·Δφ, so
// Σ_j cos(m φ_j) X_j[s, l'] = cos(m d_s) C_m[l'] + sin(m d_s) S_m[l'] and
// Σ_j sin(m φ_j) X_j[s, l'] = cos(m d_s) S_m[l'] − sin(m d_s) C_m[l'];
// Rz(φ_j) mixes the rows (l, m) and (l, −m) by those two sums.
std::vector<double> wedge_fourier_matrix(const sh::WedgeOperator& op) {
  const int n = op.sh_order(), big_n = op.nlp_order(), taps = op.taps(), cols = op.cols();
  const auto mat = op.matrix();
  std::vector<double> g(static_cast<std::size_t>(op.rows()) * 2 * big_n, 0.0);
  auto at = [&](int row, int col) -> double& { return g[static_cast<std::size_t>(row) * 2 * big_n + col]; };
  for (int l = 0; l < n; ++l)
    for (int m = 0; m <= l; ++m) {
      const int rp = sh::index(l, m), rn = sh::index(l, -m);
      for (int s = 0; s < taps; ++s) {
        const double d = (op.first_tap() + s) * op.wedge_angle(), c = std::cos(m * d), sn = std::sin(m * d);
        for (int lp = 0; lp < big_n; ++lp) {
          const double p = mat[static_cast<std::size_t>(rp) * cols + s * big_n + lp];
          if (m == 0) {
            at(rp, lp) += p;
            continue;
          }
          const double q = mat[static_cast<std::size_t>(rn) * cols + s * big_n + lp];
          at(rp, lp) += p * c + q * sn;  // V_{l,m} = Σ M_{l,m}·P − M_{l,−m}·Q
          at(rp, big_n + lp) += p * sn - q * c;
          at(rn, lp) += q * c - p * sn;  // V_{l,−m} = Σ M_{l,m}·Q + M_{l,−m}·P
          at(rn, big_n + lp) += p * c + q * sn;
        }
      }
    }
  // Entries that are zero analytically (parity, m = 0 rows) come out as rounding
  // residues ~1e-16 of the largest; zeroed, the shader compiler drops their terms.
  double largest = 0.0;
  for (double v : g) largest = std::max(largest, std::abs(v));
  for (double& v : g)
    if (std::abs(v) < kResidue * largest) v = 0.0;
  return g;
}

}  // namespace skylit::gpu
