// SH basis: orthonormality by exact quadrature, conventions against hard-coded
// values (google/spherical-harmonics, math-notes §0), Gauss–Legendre accuracy.
#include "shading/sh/quadrature.h"
#include "shading/sh/sh_basis.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace skylit;

TEST(GaussLegendre, IntegratesPolynomialsExactly) {
  for (int n : {1, 2, 5, 16, 64}) {
    const auto r = sh::gauss_legendre(n, -1.0, 2.0);
    for (int deg = 0; deg <= 2 * n - 1; ++deg) {
      double s = 0;
      for (int i = 0; i < n; ++i) s += r.weights[i] * std::pow(r.nodes[i], deg);
      const double exact = (std::pow(2.0, deg + 1) - std::pow(-1.0, deg + 1)) / (deg + 1);
      EXPECT_NEAR(s, exact, 1e-12 * std::max(1.0, std::abs(exact))) << "n=" << n << " deg=" << deg;
    }
  }
}

TEST(ShBasis, OrthonormalUpToOrder8) {
  for (int order : {2, 4, 8}) {
    const auto rule = sh::sphere_product_rule(order + 1, 2 * order + 1);
    const int nc = sh::num_coeffs(order);
    std::vector<double> gram(nc * nc, 0.0);
    sh::Vec y(nc);
    for (std::size_t k = 0; k < rule.dirs.size(); ++k) {
      sh::eval_basis(order, rule.dirs[k], y);
      for (int i = 0; i < nc; ++i)
        for (int j = 0; j < nc; ++j) gram[i * nc + j] += rule.weights[k] * y[i] * y[j];
    }
    for (int i = 0; i < nc; ++i)
      for (int j = 0; j < nc; ++j) EXPECT_NEAR(gram[i * nc + j], i == j ? 1.0 : 0.0, 1e-13);
  }
}

TEST(ShBasis, MatchesHardCodedLowOrderValues) {
  // google/spherical-harmonics' hard-coded real SH (CS phase included).
  const glm::dvec3 d = glm::normalize(glm::dvec3(0.3, -0.5, 0.8));
  const double x = d.x, y = d.y, z = d.z;
  const auto v = sh::eval_basis(4, d);
  EXPECT_NEAR(v[0], 0.282094791773878, 1e-14);
  EXPECT_NEAR(v[1], -0.488602511902920 * y, 1e-14);
  EXPECT_NEAR(v[2], 0.488602511902920 * z, 1e-14);
  EXPECT_NEAR(v[3], -0.488602511902920 * x, 1e-14);
  EXPECT_NEAR(v[4], 1.092548430592079 * x * y, 1e-14);
  EXPECT_NEAR(v[5], -1.092548430592079 * y * z, 1e-14);
  EXPECT_NEAR(v[6], 0.315391565252520 * (3 * z * z - 1), 1e-14);
  EXPECT_NEAR(v[7], -1.092548430592079 * x * z, 1e-14);
  EXPECT_NEAR(v[8], 0.546274215296040 * (x * x - y * y), 1e-14);
  EXPECT_NEAR(v[9], -0.590043589926644 * y * (3 * x * x - y * y), 1e-14);
  EXPECT_NEAR(v[12], 0.373176332590115 * z * (5 * z * z - 3), 1e-14);
  EXPECT_NEAR(v[15], -0.590043589926644 * x * (x * x - 3 * y * y), 1e-14);
  for (int l = 0; l < 4; ++l)
    for (int m = -l; m <= l; ++m) EXPECT_NEAR(sh::eval_basis_one(l, m, d), v[sh::index(l, m)], 1e-14);
}

TEST(ShBasis, FastBasisMatchesDirectFormula) {
  // eval_basis (tabled norms, one Legendre pass per m, Chebyshev cos/sin) against
  // eval_basis_one (sh_norm, assoc_legendre, atan2) for every order it serves:
  // 1..kMaxOrder, 2·kMaxOrder (reconstruct) and beyond (norms not tabled).
  std::vector<glm::dvec3> dirs = {{0, 0, 1},  {0, 0, -1}, {1, 0, 0},         {0, 1, 0},
                                  {-1, 0, 0}, {0, -1, 0}, {1e-9, -2e-9, 1}, {-3e-12, 1e-12, -1}};
  std::mt19937_64 rng(12345);
  std::normal_distribution<double> g;
  while (dirs.size() < 1000) {
    const glm::dvec3 v(g(rng), g(rng), g(rng));
    if (glm::length(v) > 1e-3) dirs.push_back(glm::normalize(v));
  }
  std::vector<int> orders;
  for (int n = 1; n <= sh::kMaxOrder; ++n) orders.push_back(n);
  orders.push_back(2 * sh::kMaxOrder);
  orders.push_back(2 * sh::kMaxOrder + 2);
  for (int order : orders) {
    sh::Vec y(sh::num_coeffs(order));
    for (const glm::dvec3& d : dirs) {
      sh::eval_basis(order, d, y);
      for (int l = 0; l < order; ++l)
        for (int m = -l; m <= l; ++m)
          ASSERT_NEAR(y[sh::index(l, m)], sh::eval_basis_one(l, m, d), 1e-13)
              << "order " << order << " l " << l << " m " << m << " dir " << d.x << ' ' << d.y << ' ' << d.z;
    }
  }
}

TEST(ShBasis, ProjectReconstructRoundTrip) {
  const int order = 6;
  sh::Vec c(sh::num_coeffs(order));
  for (std::size_t i = 0; i < c.size(); ++i) c[i] = std::sin(1.7 * i + 0.3);
  const auto rule = sh::sphere_product_rule(order + 1, 2 * order + 1);
  const auto back = sh::project(order, rule, [&](const glm::dvec3& d) { return sh::reconstruct(c, d); });
  for (std::size_t i = 0; i < c.size(); ++i) EXPECT_NEAR(back[i], c[i], 1e-13);
}

TEST(ShBasis, OrderOfRejectsNonSquares) {
  EXPECT_EQ(sh::order_of(16), 4);
  EXPECT_THROW(sh::order_of(15), std::invalid_argument);
}
