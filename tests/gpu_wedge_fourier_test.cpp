// The surface kernel's Fourier form of the wedge assembly (gpu/wedge_fourier.h)
// against sh::WedgeOperator::assemble on random slices: the same sum regrouped, so
// they agree to double rounding for every interpolation, order and W.
#include "gpu/wedge_fourier.h"
#include "shading/sh/sh_basis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <tuple>

using namespace skylit;

namespace {

// Both sides sum W·taps·N·n² products of O(1) terms.
constexpr double kTol = 1e-12;

class WedgeFourier : public ::testing::TestWithParam<std::tuple<int, int, int, sh::WedgeInterpolation>> {};

TEST_P(WedgeFourier, MatchesAssembly) {
  const auto [n, big_n, w, interp] = GetParam();
  const sh::WedgeOperator& op = sh::wedge_operator(n, big_n, w, interp);
  const std::vector<double> g = gpu::wedge_fourier_matrix(op);
  ASSERT_EQ(g.size(), static_cast<std::size_t>(n * n * 2 * big_n));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> slices(static_cast<std::size_t>(w) * big_n);
  for (double& v : slices) v = u(rng);
  const sh::Vec want = op.assemble(slices);

  std::vector<double> cs(static_cast<std::size_t>(n) * 2 * big_n, 0.0);  // [m][C | S][l']
  for (int k = 0; k < w; ++k)
    for (int m = 0; m < n; ++m)
      for (int lp = 0; lp < big_n; ++lp) {
        const double v = slices[static_cast<std::size_t>(k) * big_n + lp];
        cs[(m * 2) * big_n + lp] += std::cos(m * op.sample_azimuth(k)) * v;
        cs[(m * 2 + 1) * big_n + lp] += std::sin(m * op.sample_azimuth(k)) * v;
      }
  double scale = 0.0;
  for (double v : want) scale = std::max(scale, std::abs(v));
  for (int l = 0; l < n; ++l)
    for (int m = -l; m <= l; ++m) {
      const int r = sh::index(l, m), am = std::abs(m);
      double got = 0.0;
      for (int c = 0; c < 2 * big_n; ++c) got += g[static_cast<std::size_t>(r) * 2 * big_n + c] * cs[am * 2 * big_n + c];
      EXPECT_NEAR(got, want[r], kTol * std::max(scale, 1.0)) << "l=" << l << " m=" << m;
    }
}

INSTANTIATE_TEST_SUITE_P(Operators, WedgeFourier,
                         ::testing::Values(std::make_tuple(4, 8, 32, sh::WedgeInterpolation::Linear),
                                           std::make_tuple(4, 8, 32, sh::WedgeInterpolation::BSpline),
                                           std::make_tuple(2, 2, 3, sh::WedgeInterpolation::Linear),
                                           std::make_tuple(6, 10, 17, sh::WedgeInterpolation::BSpline),
                                           std::make_tuple(8, 16, 64, sh::WedgeInterpolation::Linear)));

}  // namespace
