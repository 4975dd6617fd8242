// Wedge operators (math-notes §3): M against brute-force 2-D quadrature of the
// interpolated wedge and against the closed-form azimuthal × sympy polar
// moments; assembly exact for a constant horizon at any W; convergence in W
// against the exact projection of a non-symmetric horizon (visibility_truth).
#include "shading/sh/nlp.h"
#include "shading/sh/quadrature.h"
#include "shading/sh/sh_basis.h"
#include "shading/sh/wedge.h"
#include "shading/visibility_truth.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <thread>

using namespace skylit;
using sh::WedgeInterpolation;

namespace {

constexpr double kPi = std::numbers::pi;
// Both routes are exact quadratures of smooth integrands: rounding only.
constexpr double kMatrixTol = 1e-13;
// Assembly sums W·n²·taps·N terms of O(1): still rounding.
constexpr double kAssemblyTol = 1e-12;
// math-notes prints six decimals.
constexpr double kTableTol = 1e-6;

double norm(const sh::Vec& a, const sh::Vec& b) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(s);
}

// ∫∫ over the canonical wedge of w_s(φ/Δφ)·P̂_l'(cos θ)·y_r(θ, φ), by GL in φ and in θ.
std::vector<double> brute_force_matrix(int n, int big_n, int w, WedgeInterpolation interp) {
  const int taps = sh::interpolation_taps(interp), nc = n * n, nk = taps * big_n;
  const double dphi = 2 * kPi / w;
  const auto gphi = sh::gauss_legendre(48, 0.0, dphi), gtheta = sh::gauss_legendre(48, 0.0, kPi);
  std::vector<double> m(nc * nk, 0.0);
  sh::Vec y(nc);
  double wt[4];
  for (int a = 0; a < 48; ++a) {
    sh::interpolation_weights(interp, gphi.nodes[a] / dphi, wt);
    for (int b = 0; b < 48; ++b) {
      const double theta = gtheta.nodes[b];
      sh::eval_basis(n, sh::direction(theta, gphi.nodes[a]), y);
      const auto p = sh::nlp_basis(big_n, std::cos(theta));
      const double weight = gphi.weights[a] * gtheta.weights[b] * std::sin(theta);
      for (int r = 0; r < nc; ++r)
        for (int s = 0; s < taps; ++s)
          for (int lp = 0; lp < big_n; ++lp) m[r * nk + s * big_n + lp] += weight * wt[s] * p[lp] * y[r];
    }
  }
  return m;
}

// Direct projection of the cap visibility {e > σ}: only y_l0, 2π ∫_{sin σ}^1 K_l0 P_l dz.
sh::Vec cap_visibility_projection(int n, double sigma) {
  sh::Vec v(n * n, 0.0);
  const auto gl = sh::gauss_legendre(n + 1, std::sin(sigma), 1.0);
  for (int l = 0; l < n; ++l)
    for (std::size_t q = 0; q < gl.nodes.size(); ++q)
      v[sh::index(l, 0)] += gl.weights[q] * 2 * kPi * sh::sh_norm(l, 0) * sh::legendre(l, gl.nodes[q]);
  return v;
}

double varying_horizon(double phi) {
  return 0.35 + 0.3 * std::cos(phi - 0.4) + 0.15 * std::sin(2 * phi + 1) + 0.1 * std::cos(3 * phi);
}

const sh::Vec& varying_horizon_exact() {
  static const sh::Vec exact = [] {
    shading::Occluders occ;
    occ.horizon = varying_horizon;
    return shading::project_visibility(4, occ);
  }();
  return exact;
}

sh::Vec assemble_varying(int n, int big_n, int w, WedgeInterpolation interp) {
  const auto& op = sh::wedge_operator(n, big_n, w, interp);
  std::vector<double> sigma(w);
  for (int j = 0; j < w; ++j) sigma[j] = varying_horizon(op.sample_azimuth(j));
  return sh::visibility_from_horizon(op, sigma);
}

// ‖a − b‖ restricted to coefficients with |m| of the given parity.
double parity_error(const sh::Vec& a, const sh::Vec& b, int parity) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const int l = sh::band_of(static_cast<int>(i)), m = static_cast<int>(i) - l * (l + 1);
    if (std::abs(m) % 2 == parity) s += (a[i] - b[i]) * (a[i] - b[i]);
  }
  return std::sqrt(s);
}

}  // namespace

TEST(WedgeInterpolation, WeightsPartitionUnityAndMatchListingConstants) {
  double w[4];
  sh::interpolation_weights(WedgeInterpolation::BSpline, 0.0, w);
  EXPECT_NEAR(w[0], 1.0 / 6, 1e-15);
  EXPECT_NEAR(w[1], 2.0 / 3, 1e-15);
  EXPECT_NEAR(w[2], 1.0 / 6, 1e-15);
  EXPECT_NEAR(w[3], 0.0, 1e-15);
  // NS09-S W_mid_and_knot[1].
  sh::interpolation_weights(WedgeInterpolation::BSpline, 0.5, w);
  EXPECT_NEAR(w[0], 1.0 / 48, 1e-15);
  EXPECT_NEAR(w[1], 23.0 / 48, 1e-15);
  EXPECT_NEAR(w[2], 23.0 / 48, 1e-15);
  EXPECT_NEAR(w[3], 1.0 / 48, 1e-15);
  for (double a : {0.0, 0.13, 0.5, 0.77, 1.0}) {
    sh::interpolation_weights(WedgeInterpolation::BSpline, a, w);
    EXPECT_NEAR(w[0] + w[1] + w[2] + w[3], 1.0, 1e-15);
    sh::interpolation_weights(WedgeInterpolation::Linear, a, w);
    EXPECT_NEAR(w[0] + w[1], 1.0, 1e-15);
    EXPECT_NEAR(w[1], a, 1e-15);
  }
  // The spline continues across knots: weights at α = 1 equal those at α = 0 shifted one tap.
  double w1[4];
  sh::interpolation_weights(WedgeInterpolation::BSpline, 1.0, w1);
  sh::interpolation_weights(WedgeInterpolation::BSpline, 0.0, w);
  for (int s = 0; s < 3; ++s) EXPECT_NEAR(w1[s + 1], w[s], 1e-15);
}

TEST(WedgeOperator, ShapesAreTapsTimesNlpOrder) {
  const auto& lin = sh::wedge_operator(4, 4, 32, WedgeInterpolation::Linear);
  const auto& bspl = sh::wedge_operator(4, 4, 32, WedgeInterpolation::BSpline);
  EXPECT_EQ(lin.rows(), 16);
  EXPECT_EQ(lin.cols(), 8);
  EXPECT_EQ(bspl.rows(), 16);
  EXPECT_EQ(bspl.cols(), 16);  // 16 × 16, not NS09's "16 × 32"
  EXPECT_EQ(lin.matrix().size(), 128u);
  EXPECT_EQ(bspl.matrix_f32().size(), 256u);
  for (std::size_t i = 0; i < bspl.matrix().size(); ++i)
    EXPECT_EQ(bspl.matrix_f32()[i], static_cast<float>(bspl.matrix()[i]));
}

TEST(WedgeOperator, MatchesBruteForceQuadratureOfTheInterpolatedWedge) {
  struct Case {
    int n, big_n, w;
    WedgeInterpolation interp;
  };
  const Case cases[] = {{4, 4, 32, WedgeInterpolation::Linear}, {4, 8, 32, WedgeInterpolation::BSpline},
                        {4, 4, 7, WedgeInterpolation::BSpline}, {3, 5, 1, WedgeInterpolation::Linear},
                        {2, 3, 1, WedgeInterpolation::BSpline}, {8, 16, 12, WedgeInterpolation::Linear},
                        {1, 2, 3, WedgeInterpolation::Linear}};
  for (const auto& c : cases) {
    const sh::WedgeOperator op(c.n, c.big_n, c.w, c.interp);
    const auto bf = brute_force_matrix(c.n, c.big_n, c.w, c.interp);
    ASSERT_EQ(op.matrix().size(), bf.size());
    for (std::size_t i = 0; i < bf.size(); ++i)
      EXPECT_NEAR(op.matrix()[i], bf[i], kMatrixTol)
          << "n=" << c.n << " N=" << c.big_n << " W=" << c.w << " entry " << i;
  }
}

TEST(WedgeOperator, LinearMatrixIsClosedFormAzimuthalTimesPolarMoments) {
  // Polar moments B[l,|m|,l'] from sympy (math-notes §3, CS phase), l, l' < 4.
  const double sp = std::sqrt(kPi);
  auto polar = [&](int l, int mu, int lp) -> double {
    if (mu == 0) return l == lp ? 1 / std::sqrt(2 * kPi) : 0.0;
    const double t[4][4][4] = {{},
                               {{}, {-std::sqrt(3 * kPi) / 8, 0, std::sqrt(15 * kPi) / 64, 0}},
                               {{},
                                {0, -3 * std::sqrt(5 * kPi) / 32, 0, std::sqrt(105 * kPi) / 128},
                                {std::sqrt(15.0) / (6 * sp), 0, -std::sqrt(3.0) / (6 * sp), 0}},
                               {{},
                                {-std::sqrt(42 * kPi) / 128, 0, -7 * std::sqrt(210 * kPi) / 512, 0},
                                {0, std::sqrt(35.0) / (10 * sp), 0, -std::sqrt(15.0) / (10 * sp)},
                                {-3 * std::sqrt(70 * kPi) / 128, 0, 15 * std::sqrt(14 * kPi) / 512, 0}}};
    return t[l][mu][lp];
  };
  // Azimuthal moments of the linear weights in closed form.
  auto azimuthal = [](int m, int s, double d) {
    if (m == 0) return d / 2;
    const double mu = std::abs(m), sn = std::sin(mu * d), cs = std::cos(mu * d), r2 = std::sqrt(2.0);
    const double a1 = m > 0 ? r2 * (sn / mu + (cs - 1) / (mu * mu * d)) : r2 * (-cs / mu + sn / (mu * mu * d));
    const double total = m > 0 ? r2 * sn / mu : r2 * (1 - cs) / mu;
    return s == 1 ? a1 : total - a1;
  };
  for (int w : {1, 5, 32}) {
    const auto& op = sh::wedge_operator(4, 4, w, WedgeInterpolation::Linear);
    for (int l = 0; l < 4; ++l)
      for (int m = -l; m <= l; ++m)
        for (int s = 0; s < 2; ++s)
          for (int lp = 0; lp < 4; ++lp)
            EXPECT_NEAR(op.matrix()[sh::index(l, m) * 8 + s * 4 + lp],
                        azimuthal(m, s, op.wedge_angle()) * polar(l, std::abs(m), lp), kMatrixTol)
                << "W=" << w << " l=" << l << " m=" << m << " s=" << s << " l'=" << lp;
  }
}

TEST(WedgeOperator, MatchesMathNotesLinearTableAtW32) {
  const auto& op = sh::wedge_operator(4, 4, 32, WedgeInterpolation::Linear);
  struct Row {
    int i;
    double v[8];
  };
  const Row rows[] = {
      {0, {0.039166, 0, 0, 0, 0.039166, 0, 0, 0}},
      {1, {-0.003480, 0, 0.000973, 0, -0.006947, 0, 0.001942, 0}},
      {3, {-0.053109, 0, 0.014844, 0, -0.052767, 0, 0.014749, 0}},
      {8, {0.049917, 0, -0.022323, 0, 0.048630, 0, -0.021748, 0}},
      {10, {0, 0.006020, 0, -0.003941, 0, 0.011946, 0, -0.007821}},
      {15, {-0.046877, 0, 0.026205, 0, -0.044150, 0, 0.024681, 0}},
  };
  for (const auto& r : rows)
    for (int c = 0; c < 8; ++c)
      EXPECT_NEAR(op.matrix()[r.i * 8 + c], r.v[c], kTableTol) << "row " << r.i << " col " << c;
}

TEST(WedgeAssembly, ConstantHorizonEqualsCapProjectionForAnyW) {
  const double log_eps = std::log(0.1);
  for (int n : {4, 8})
    for (int big_n : {n, 2 * n})
      for (auto interp : {WedgeInterpolation::Linear, WedgeInterpolation::BSpline})
        for (int w : {1, 3, 8, 32})
          for (double deg : {-20.0, 0.0, 15.0, 40.0}) {
            const double sigma = deg * kPi / 180;
            const auto& op = sh::wedge_operator(n, big_n, w, interp);
            const std::vector<double> horizon(w, sigma);
            const auto vis = sh::visibility_from_horizon(op, horizon);
            const auto logvis = sh::log_visibility_from_horizon(op, horizon, log_eps);
            const auto exact = cap_visibility_projection(n, sigma);
            for (int i = 0; i < n * n; ++i) {
              const double exact_log = log_eps * ((i == 0 ? sh::kSqrt4Pi : 0.0) - exact[i]);
              EXPECT_NEAR(vis[i], exact[i], kAssemblyTol) << "n=" << n << " N=" << big_n << " W=" << w << " σ=" << deg;
              EXPECT_NEAR(logvis[i], exact_log, kAssemblyTol) << "n=" << n << " N=" << big_n << " W=" << w;
            }
          }
}

TEST(WedgeAssembly, VaryingHorizonErrorFallsAsInverseSquareOfW) {
  // NLP order 4n: the slice truncation is negligible, leaving the O(W⁻²)
  // interpolation error; a wrong rotation sign or a missing wedge would be O(1).
  const auto& exact = varying_horizon_exact();
  for (auto interp : {WedgeInterpolation::Linear, WedgeInterpolation::BSpline}) {
    double prev = 0;
    for (int w : {8, 16, 32, 64}) {
      const double err = norm(assemble_varying(4, 16, w, interp), exact);
      if (w == 8) {
        EXPECT_LT(err, 0.15);
      } else {
        EXPECT_GT(prev / err, 3.0) << "W=" << w << " interp=" << static_cast<int>(interp);
      }
      prev = err;
    }
  }
}

TEST(WedgeAssembly, OddMFloorAtNEqualsNIsRemovedByHigherNlpOrder) {
  // math-notes §3 / §10.18: with N = n the odd-|m| error stays ≈ constant in W,
  // the even-|m| error falls as W⁻²; N = 2n cuts the odd-|m| floor.
  const auto& exact = varying_horizon_exact();
  const auto v32 = assemble_varying(4, 4, 32, WedgeInterpolation::Linear);
  const auto v128 = assemble_varying(4, 4, 128, WedgeInterpolation::Linear);
  const double odd32 = parity_error(v32, exact, 1), odd128 = parity_error(v128, exact, 1);
  EXPECT_NEAR(odd128 / odd32, 1.0, 0.1);
  EXPECT_GT(parity_error(v32, exact, 0) / parity_error(v128, exact, 0), 10.0);
  const auto v128_n8 = assemble_varying(4, 8, 128, WedgeInterpolation::Linear);
  EXPECT_LT(parity_error(v128_n8, exact, 1), odd128 / 5);
}

TEST(WedgeAssembly, LogVisibilityIsLogEpsTimesOcclusionOfTheSameAssembly) {
  const auto& op = sh::wedge_operator(4, 8, 16, WedgeInterpolation::BSpline);
  std::vector<double> sigma(16);
  for (int j = 0; j < 16; ++j) sigma[j] = varying_horizon(op.sample_azimuth(j)) - 0.5;  // some below 0
  const double log_eps = std::log(0.05);
  const auto vis = sh::visibility_from_horizon(op, sigma);
  const auto logvis = sh::log_visibility_from_horizon(op, sigma, log_eps);
  for (int i = 0; i < 16; ++i) EXPECT_NEAR(logvis[i], log_eps * ((i == 0 ? sh::kSqrt4Pi : 0.0) - vis[i]), kAssemblyTol);
}

TEST(WedgeAssembly, SpanFormsUseCallerScratchAndCheckSizes) {
  const auto& op = sh::wedge_operator(4, 4, 8, WedgeInterpolation::Linear);
  std::vector<double> sigma(8, 0.2), scratch(8 * 4), out(16);
  sh::visibility_from_horizon(op, sigma, scratch, out);
  const auto ref = sh::visibility_from_horizon(op, sigma);
  for (int i = 0; i < 16; ++i) EXPECT_EQ(out[i], ref[i]);
  std::vector<double> small(8 * 4 - 1);
  EXPECT_THROW(sh::visibility_from_horizon(op, sigma, small, out), std::invalid_argument);
  EXPECT_THROW(sh::visibility_from_horizon(op, std::vector<double>(7, 0.2)), std::invalid_argument);
  EXPECT_THROW(sh::WedgeOperator(4, 3, 8, WedgeInterpolation::Linear), std::invalid_argument);
  EXPECT_THROW(sh::WedgeOperator(4, 4, 0, WedgeInterpolation::Linear), std::invalid_argument);
}

TEST(WedgeOperator, CacheReturnsOneOperatorAcrossThreads) {
  const sh::WedgeOperator* seen[4] = {};
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&seen, t] { seen[t] = &sh::wedge_operator(5, 7, 19, WedgeInterpolation::BSpline); });
  for (auto& t : threads) t.join();
  for (int t = 1; t < 4; ++t) EXPECT_EQ(seen[t], seen[0]);
  EXPECT_EQ(&sh::wedge_operator(5, 7, 19, WedgeInterpolation::BSpline), seen[0]);
  EXPECT_NE(&sh::wedge_operator(5, 7, 19, WedgeInterpolation::Linear), seen[0]);
}
