// NLP basis and slice vectors: closed forms against Gauss–Legendre quadrature
// at several orders, the printed order-4 table (math-notes T2), and the cap ZH
// (math-notes §2, §4) by an independent quadrature and closed form.
#include "shading/sh/nlp.h"
#include "shading/sh/quadrature.h"
#include "shading/sh/sh_basis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace skylit;

namespace {

// All quantities are O(1); quadrature of polynomials is exact up to rounding.
constexpr double kQuadratureTol = 1e-12;
// math-notes T2 prints six decimals.
constexpr double kTableTol = 1e-6;

const double kSigmas[] = {-1.5, -0.7, -0.2, 0.0, 0.1, 0.5, 1.0, 1.3, 1.5, 1.5707};

// o_l = ∫_{−1}^{sin σ} P̂_l(z) dz by GL exact for degree l, with P̂ from sh::legendre.
double occlusion_by_quadrature(int l, double sigma) {
  const auto gl = sh::gauss_legendre(l / 2 + 2, -1.0, std::sin(sigma));
  double s = 0.0;
  for (std::size_t q = 0; q < gl.nodes.size(); ++q)
    s += gl.weights[q] * std::sqrt((2 * l + 1) / 2.0) * sh::legendre(l, gl.nodes[q]);
  return s;
}

}  // namespace

TEST(NlpBasis, OrthonormalOnMinusOneOne) {
  const int order = 20;
  const auto gl = sh::gauss_legendre(order + 1);
  std::vector<double> gram(order * order, 0.0);
  for (std::size_t q = 0; q < gl.nodes.size(); ++q) {
    const auto p = sh::nlp_basis(order, gl.nodes[q]);
    for (int i = 0; i < order; ++i)
      for (int j = 0; j < order; ++j) gram[i * order + j] += gl.weights[q] * p[i] * p[j];
  }
  for (int i = 0; i < order; ++i)
    for (int j = 0; j < order; ++j) EXPECT_NEAR(gram[i * order + j], i == j ? 1.0 : 0.0, kQuadratureTol);
}

TEST(NlpBasis, MatchesOrder4PolynomialsAndZonalHarmonics) {
  for (double z : {-0.9, -0.3, 0.0, 0.4, 0.95}) {
    const auto p = sh::nlp_basis(4, z);
    EXPECT_NEAR(p[0], 1 / std::sqrt(2.0), 1e-15);
    EXPECT_NEAR(p[1], std::sqrt(1.5) * z, 1e-15);
    EXPECT_NEAR(p[2], std::sqrt(2.5) * (3 * z * z - 1) / 2, 1e-15);
    EXPECT_NEAR(p[3], std::sqrt(3.5) * (5 * z * z * z - 3 * z) / 2, 1e-15);
    // y_l0 = P̂_l(cos θ)/√(2π).
    const glm::dvec3 d(std::sqrt(1 - z * z), 0.0, z);
    for (int l = 0; l < 4; ++l) EXPECT_NEAR(sh::eval_basis_one(l, 0, d), p[l] / std::sqrt(2 * std::numbers::pi), 1e-15);
  }
}

TEST(NlpOcclusion, ClosedFormEqualsQuadratureAtManyOrders) {
  for (int order : {1, 2, 4, 8, 16, 32}) {
    for (double sigma : kSigmas) {
      const auto o = sh::nlp_occlusion(order, sigma);
      for (int l = 0; l < order; ++l)
        EXPECT_NEAR(o[l], occlusion_by_quadrature(l, sigma), kQuadratureTol)
            << "order " << order << " l " << l << " sigma " << sigma;
    }
  }
}

TEST(NlpOcclusion, MatchesPrintedOrder4FormAndPaperRelation) {
  // The printed NS09 §4 / LSH eq. 16 form, written in s = sin σ and c² = cos² σ.
  for (double sigma : kSigmas) {
    const double s = std::sin(sigma), c2 = std::cos(sigma) * std::cos(sigma);
    const auto o = sh::nlp_occlusion(4, sigma);
    EXPECT_NEAR(o[0], (1 + s) / std::sqrt(2.0), 1e-15);
    EXPECT_NEAR(o[1], -std::sqrt(6.0) / 4 * c2, 1e-15);
    EXPECT_NEAR(o[2], -std::sqrt(10.0) / 4 * s * c2, 1e-15);
    EXPECT_NEAR(o[3], std::sqrt(14.0) / 16 * c2 * (5 * c2 - 4), 1e-15);
    // The general closed form (P_{l+1} − P_{l−1})/(2l+1) for l ≥ 1.
    for (int l = 1; l < 4; ++l)
      EXPECT_NEAR(o[l], sh::nlp_norm(l) * (sh::legendre(l + 1, s) - sh::legendre(l - 1, s)) / (2 * l + 1), 1e-15);
  }
}

TEST(NlpOcclusion, MatchesMathNotesTableT2) {
  struct Row {
    double deg, o[4], log_o[4];
  };
  const Row rows[] = {
      {-30, {0.353553, -0.459279, 0.296464, -0.043848}, {-0.814087, 1.057530, -0.682633, 0.100963}},
      {-10, {0.584319, -0.593907, 0.133141, 0.192607}, {-1.345444, 1.367522, -0.306569, -0.443495}},
      {0, {0.707107, -0.612372, 0, 0.233854}, {-1.628174, 1.410040, 0, -0.538468}},
      {20, {0.948952, -0.540738, -0.238761, 0.085720}, {-2.185042, 1.245096, 0.549767, -0.197377}},
      {45, {1.207107, -0.306186, -0.279508, -0.175390}, {-2.779466, 0.705020, 0.643592, 0.403851}},
      {75, {1.390119, -0.041021, -0.051154, -0.057414}, {-3.200868, 0.094455, 0.117786, 0.132201}},
      {90, {1.414214, 0, 0, 0}, {-3.256347, 0, 0, 0}},
  };
  for (const auto& r : rows) {
    const double sigma = r.deg * std::numbers::pi / 180;
    const auto o = sh::nlp_occlusion(4, sigma);
    const auto lo = sh::nlp_log_visibility(4, sigma, std::log(0.1));
    for (int l = 0; l < 4; ++l) {
      EXPECT_NEAR(o[l], r.o[l], kTableTol) << r.deg << "° l=" << l;
      EXPECT_NEAR(lo[l], r.log_o[l], kTableTol) << r.deg << "° l=" << l;
    }
  }
}

TEST(NlpVisibility, IsFullSliceMinusOcclusionAndClampsSigma) {
  for (double sigma : kSigmas) {
    const auto o = sh::nlp_occlusion(8, sigma);
    const auto v = sh::nlp_visibility(8, sigma);
    EXPECT_NEAR(v[0] + o[0], std::sqrt(2.0), 1e-15);
    for (int l = 1; l < 8; ++l) EXPECT_NEAR(v[l] + o[l], 0.0, 1e-15);
  }
  const auto above = sh::nlp_visibility(6, 2.5), top = sh::nlp_visibility(6, std::numbers::pi / 2);
  const auto below = sh::nlp_occlusion(6, -4.0);
  for (int l = 0; l < 6; ++l) {
    EXPECT_NEAR(above[l], top[l], 1e-15);
    EXPECT_NEAR(above[l], 0.0, 1e-15);
    EXPECT_NEAR(below[l], 0.0, 1e-15);
  }
}

TEST(NlpVisibility, TimesSqrt2PiIsTheCapZonalHarmonic) {
  for (double sigma : kSigmas) {
    const int order = 8;
    const auto v = sh::nlp_visibility(order, sigma);
    // Cap {e > σ} = {θ ≤ α}, α = π/2 − σ, c = cos α = sin σ.
    const double c = std::sin(sigma);
    const auto gl = sh::gauss_legendre(order + 2, c, 1.0);
    for (int l = 0; l < order; ++l) {
      // Projection onto y_l0 by quadrature: 2π ∫_c^1 K_l0 P_l(z) dz.
      double proj = 0.0;
      for (std::size_t q = 0; q < gl.nodes.size(); ++q)
        proj += gl.weights[q] * 2 * std::numbers::pi * sh::sh_norm(l, 0) * sh::legendre(l, gl.nodes[q]);
      // Cap-indicator closed form (math-notes §4).
      const double closed = l == 0 ? std::sqrt(std::numbers::pi) * (1 - c)
                                   : std::sqrt(std::numbers::pi * (2 * l + 1)) *
                                         (sh::legendre(l - 1, c) - sh::legendre(l + 1, c)) / (2 * l + 1);
      EXPECT_NEAR(std::sqrt(2 * std::numbers::pi) * v[l], proj, kQuadratureTol) << "l " << l << " sigma " << sigma;
      EXPECT_NEAR(std::sqrt(2 * std::numbers::pi) * v[l], closed, kQuadratureTol) << "l " << l << " sigma " << sigma;
    }
  }
}

TEST(NlpOcclusion, SpanFormWritesOnlyTheGivenOrder) {
  double buf[6] = {9, 9, 9, 9, 9, 9};
  sh::nlp_occlusion(0.3, std::span<double>(buf, 5));
  const auto o = sh::nlp_occlusion(5, 0.3);
  for (int l = 0; l < 5; ++l) EXPECT_EQ(buf[l], o[l]);
  EXPECT_EQ(buf[5], 9.0);
}
