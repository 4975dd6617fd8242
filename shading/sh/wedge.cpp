#include "shading/sh/wedge.h"

#include "shading/sh/nlp.h"
#include "shading/sh/quadrature.h"

#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <tuple>

namespace skylit::sh {

int interpolation_taps(WedgeInterpolation interp) { return interp == WedgeInterpolation::Linear ? 2 : 4; }

int interpolation_first_tap(WedgeInterpolation interp) { return interp == WedgeInterpolation::Linear ? 0 : -1; }

void interpolation_weights(WedgeInterpolation interp, double a, std::span<double> w) {
  if (w.size() < static_cast<std::size_t>(interpolation_taps(interp)))
    throw std::invalid_argument("interpolation_weights: span too small");
  if (interp == WedgeInterpolation::Linear) {
    w[0] = 1.0 - a;
    w[1] = a;
    return;
  }
  // Uniform cubic B-spline; at α = 0 and ½ these are NS09-S's W_mid_and_knot.
  const double b = 1.0 - a, a2 = a * a, a3 = a2 * a;
  w[0] = b * b * b / 6.0;
  w[1] = (3 * a3 - 6 * a2 + 4) / 6.0;
  w[2] = (-3 * a3 + 3 * a2 + 3 * a + 1) / 6.0;
  w[3] = a3 / 6.0;
}

namespace {

// A_{m,s} = ∫_0^Δφ w_s(φ/Δφ) Φ_m(φ) dφ, Φ_0 = 1, Φ_{m>0} = √2 cos mφ, Φ_{m<0} = √2 sin|m|φ.
// The integrand is a cubic times a trigonometric term of frequency < 8 over at
// most 2π: 64 Gauss–Legendre nodes reach rounding (checked against the closed
// form of the linear moments in wedge_test).
double azimuthal_moment(int m, int tap, double dphi, WedgeInterpolation interp, const sh::Rule1D& unit) {
  double sum = 0.0;
  std::array<double, 4> w{};
  for (std::size_t q = 0; q < unit.nodes.size(); ++q) {
    const double alpha = unit.nodes[q], phi = alpha * dphi;
    interpolation_weights(interp, alpha, w);
    const double basis = m == 0  ? 1.0
                         : m > 0 ? std::sqrt(2.0) * std::cos(m * phi)
                                 : std::sqrt(2.0) * std::sin(-m * phi);
    sum += unit.weights[q] * w[tap] * basis;
  }
  return sum * dphi;
}

// B_{l,μ,l'} = ∫_{−1}^{1} P̂_l'(z) K_lμ P_l^μ(z) dz, exactly:
// even μ: a polynomial of degree l + l' → Gauss–Legendre;
// odd μ: √(1−z²) × a polynomial of degree l − 1 + l' → Gauss–Chebyshev (2nd kind)
// with as many nodes as the Gauss–Legendre rule `gl`.
double polar_moment(int l, int mu, int lp, const sh::Rule1D& gl) {
  double sum = 0.0;
  const int nodes = static_cast<int>(gl.nodes.size());
  if (mu % 2 == 0) {
    for (int q = 0; q < nodes; ++q) {
      const double z = gl.nodes[q];
      sum += gl.weights[q] * nlp_basis_one(lp, z) * assoc_legendre(l, mu, z);
    }
  } else {
    for (int k = 1; k <= nodes; ++k) {
      const double t = k * kPi / (nodes + 1), z = std::cos(t), st = std::sin(t);
      const double weight = kPi / (nodes + 1) * st * st;
      sum += weight * nlp_basis_one(lp, z) * assoc_legendre(l, mu, z) / st;
    }
  }
  return sh_norm(l, mu) * sum;
}

}  // namespace

WedgeOperator::WedgeOperator(int sh_order, int nlp_order, int azimuths, WedgeInterpolation interp)
    : sh_order_(sh_order), nlp_order_(nlp_order), azimuths_(azimuths), interp_(interp) {
  if (sh_order < kMinOrder || sh_order > kMaxOrder || nlp_order < sh_order || nlp_order > kMaxNlpOrder || azimuths < 1)
    throw std::invalid_argument("WedgeOperator: need 1 ≤ n ≤ 8, n ≤ N ≤ 64, W ≥ 1; got n=" + std::to_string(sh_order) +
                                " N=" + std::to_string(nlp_order) + " W=" + std::to_string(azimuths));
  const int n = sh_order, big_n = nlp_order, t = taps(), nk = cols();
  const double dphi = wedge_angle();
  const auto unit = sh::gauss_legendre(64, 0.0, 1.0);
  const auto polar_rule = sh::gauss_legendre(n + big_n + 4);  // exact: 2·nodes − 1 ≥ l + l'

  matrix_.assign(static_cast<std::size_t>(rows()) * nk, 0.0);
  for (int l = 0; l < n; ++l)
    for (int m = -l; m <= l; ++m) {
      const int mu = std::abs(m);
      std::array<double, 4> a{};
      for (int s = 0; s < t; ++s) a[s] = azimuthal_moment(m, s, dphi, interp, unit);
      for (int lp = 0; lp < big_n; ++lp) {
        if ((l - mu - lp) % 2 != 0) continue;  // B vanishes unless l' ≡ l − |m| (mod 2)
        const double b = polar_moment(l, mu, lp, polar_rule);
        for (int s = 0; s < t; ++s) matrix_[static_cast<std::size_t>(index(l, m)) * nk + s * big_n + lp] = a[s] * b;
      }
    }
  matrix_f32_.assign(matrix_.begin(), matrix_.end());
  columns_.resize(matrix_.size());
  for (int r = 0; r < rows(); ++r)
    for (int c = 0; c < nk; ++c)
      columns_[static_cast<std::size_t>(c) * rows() + r] = matrix_[static_cast<std::size_t>(r) * nk + c];

  cos_m_phi_.resize(static_cast<std::size_t>(azimuths) * n);
  sin_m_phi_.resize(cos_m_phi_.size());
  for (int j = 0; j < azimuths; ++j)
    for (int m = 0; m < n; ++m) {
      cos_m_phi_[j * n + m] = std::cos(m * sample_azimuth(j));
      sin_m_phi_[j * n + m] = std::sin(m * sample_azimuth(j));
    }
}

double WedgeOperator::wedge_angle() const { return 2.0 * kPi / azimuths_; }

double WedgeOperator::sample_azimuth(int j) const { return j * wedge_angle(); }

void WedgeOperator::assemble(std::span<const double> slices, std::span<double> out) const {
  const int n = sh_order_, big_n = nlp_order_, w = azimuths_, t = taps(), nc = rows();
  if (slices.size() != static_cast<std::size_t>(w) * big_n || out.size() != static_cast<std::size_t>(nc))
    throw std::invalid_argument("WedgeOperator::assemble: need W·N slice values and n² outputs");
  std::fill(out.begin(), out.end(), 0.0);
  std::array<const double*, 4> tap{};
  std::array<double, kMaxOrder * kMaxOrder> wedge{};
  for (int j = 0; j < w; ++j) {
    for (int s = 0; s < t; ++s) tap[s] = &slices[static_cast<std::size_t>(((j + first_tap() + s) % w + w) % w) * big_n];
    // wedge = M · [taps]: column by column, so the inner loop runs over contiguous rows.
    std::fill_n(wedge.begin(), nc, 0.0);
    for (int s = 0; s < t; ++s)
      for (int lp = 0; lp < big_n; ++lp) {
        const double x = tap[s][lp];
        const double* col = &columns_[static_cast<std::size_t>(s * big_n + lp) * nc];
        for (int r = 0; r < nc; ++r) wedge[r] += col[r] * x;
      }
    // Rz(φ_j): the canonical wedge [0, Δφ] moves to [φ_j, φ_j + Δφ].
    const double* cm = &cos_m_phi_[static_cast<std::size_t>(j) * n];
    const double* sm = &sin_m_phi_[static_cast<std::size_t>(j) * n];
    for (int l = 0; l < n; ++l) out[index(l, 0)] += wedge[index(l, 0)];
    for (int m = 1; m < n; ++m)
      for (int l = m; l < n; ++l) {
        const double a = wedge[index(l, m)], b = wedge[index(l, -m)];
        out[index(l, m)] += a * cm[m] - b * sm[m];
        out[index(l, -m)] += a * sm[m] + b * cm[m];
      }
  }
}

Vec WedgeOperator::assemble(std::span<const double> slices) const {
  Vec out(rows());
  assemble(slices, out);
  return out;
}

const WedgeOperator& wedge_operator(int sh_order, int nlp_order, int azimuths, WedgeInterpolation interp) {
  using Key = std::tuple<int, int, int, int>;
  static std::map<Key, std::unique_ptr<WedgeOperator>> cache;
  static std::mutex mutex;
  const Key key{sh_order, nlp_order, azimuths, static_cast<int>(interp)};
  std::lock_guard lock(mutex);
  auto& slot = cache[key];
  if (!slot) {
    try {
      slot = std::make_unique<WedgeOperator>(sh_order, nlp_order, azimuths, interp);
    } catch (...) {
      cache.erase(key);
      throw;
    }
  }
  return *slot;
}

namespace {

std::span<double> slice_scratch(const WedgeOperator& op, std::span<const double> sigma, std::span<double> scratch) {
  const std::size_t need = static_cast<std::size_t>(op.azimuths()) * op.nlp_order();
  if (sigma.size() != static_cast<std::size_t>(op.azimuths()))
    throw std::invalid_argument("visibility_from_horizon: need one horizon elevation per azimuth");
  if (scratch.size() < need) throw std::invalid_argument("visibility_from_horizon: scratch smaller than W·N");
  return scratch.first(need);
}

}  // namespace

void visibility_from_horizon(const WedgeOperator& op, std::span<const double> sigma, std::span<double> scratch,
                             std::span<double> out) {
  const auto slices = slice_scratch(op, sigma, scratch);
  const std::size_t big_n = op.nlp_order();
  for (std::size_t j = 0; j < sigma.size(); ++j) nlp_visibility(sigma[j], slices.subspan(j * big_n, big_n));
  op.assemble(slices, out);
}

Vec visibility_from_horizon(const WedgeOperator& op, std::span<const double> sigma) {
  std::vector<double> scratch(static_cast<std::size_t>(op.azimuths()) * op.nlp_order());
  Vec out(op.rows());
  visibility_from_horizon(op, sigma, scratch, out);
  return out;
}

void log_visibility_from_horizon(const WedgeOperator& op, std::span<const double> sigma, double log_eps,
                                 std::span<double> scratch, std::span<double> out) {
  const auto slices = slice_scratch(op, sigma, scratch);
  const std::size_t big_n = op.nlp_order();
  for (std::size_t j = 0; j < sigma.size(); ++j)
    nlp_log_visibility(sigma[j], log_eps, slices.subspan(j * big_n, big_n));
  op.assemble(slices, out);
}

Vec log_visibility_from_horizon(const WedgeOperator& op, std::span<const double> sigma, double log_eps) {
  std::vector<double> scratch(static_cast<std::size_t>(op.azimuths()) * op.nlp_order());
  Vec out(op.rows());
  log_visibility_from_horizon(op, sigma, log_eps, scratch, out);
  return out;
}

}  // namespace skylit::sh
