// BRDF ZH vectors (shading/brdf.h) against independent derivations: brute-force
// midpoint integration in θ, the closed forms and tables of math-notes §7, and
// the sky module's clamped cosine.
#include "shading/brdf.h"
#include "shading/sh/zonal.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace skylit;
using shading::Brdf;
using shading::BrdfKind;
constexpr double kPi = sh::kPi;

namespace {

// z_l = 2π ∫_0^π f(cos θ) y_l0(θ) sin θ dθ by a plain midpoint rule in θ —
// no knowledge of kinks, so only ≈1e-7 accurate, but independent.
sh::Vec brute_zh(int order, const std::function<double(double)>& f, int steps = 400000) {
  sh::Vec z(order, 0.0);
  const double h = kPi / steps;
  for (int s = 0; s < steps; ++s) {
    const double th = (s + 0.5) * h, w = 2 * kPi * f(std::cos(th)) * std::sin(th) * h;
    for (int l = 0; l < order; ++l) z[l] += w * sh::sh_norm(l, 0) * sh::legendre(l, std::cos(th));
  }
  return z;
}

void expect_near(const sh::Vec& a, const sh::Vec& b, double tol, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t l = 0; l < a.size(); ++l) EXPECT_NEAR(a[l], b[l], tol) << what << " l=" << l;
}

}  // namespace

TEST(BrdfZh, ClampedCosineMatchesNs09) {
  expect_near(sh::clamped_cosine_zh(4), {0.886227, 1.023327, 0.495416, 0.0}, 1e-6, "math-notes §7");
  // Lambert·cos = clamped cosine / π; its DC is 1/√(4π) (albedo 1 integrates to 1).
  const auto lambert = shading::brdf_zh(4, Brdf{});
  EXPECT_NEAR(lambert[0], 1 / sh::kSqrt4Pi, 1e-15);
  EXPECT_NEAR(lambert[1] * kPi, 1.023327, 1e-6);
}

TEST(BrdfZh, PhongLobeMatchesBruteForceAndTable) {
  expect_near(shading::lobe_zh(4, 4.0), {0.282095, 0.407169, 0.360448, 0.233235}, 1e-6, "math-notes Phong r=4");
  for (double r : {1.0, 2.0, 4.0, 16.0, 2.5, 0.5}) {
    const auto z = shading::lobe_zh(8, r);
    const auto b = brute_zh(8, [r](double t) { return shading::lobe_profile(r, t); });
    expect_near(z, b, r < 1 ? 1e-6 : 1e-8, "Phong r=" + std::to_string(r));
    EXPECT_NEAR(z[0], 1 / sh::kSqrt4Pi, 1e-14) << "normalised lobe, r=" << r;
  }
}

TEST(BrdfZh, LogLobeClosedFormMatchesQuadrature) {
  for (double r : {1.0, 2.0, 3.5, 4.0, 16.0, 64.0})
    for (double eps : {1e-4, 0.01, 0.05, 0.1, 0.2, 0.3, 0.5, 2.0}) {
      const auto cf = shading::log_lobe_zh_closed_form(4, r, eps);
      const auto qd = shading::log_lobe_zh_quadrature(4, r, eps);
      expect_near(cf, qd, 1e-11, "r=" + std::to_string(r) + " eps=" + std::to_string(eps));
    }
}

TEST(BrdfZh, LogLobeQuadratureMatchesBruteForceAtOrder8) {
  for (double r : {1.0, 4.0, 16.0})
    for (double eps : {0.01, 0.1}) {
      const double k0 = (r + 1) / (2 * kPi);
      const auto b = brute_zh(8, [=](double t) { return std::log(std::max(t > 0 ? k0 * std::pow(t, r) : 0.0, eps)); });
      expect_near(shading::log_lobe_zh_quadrature(8, r, eps), b, 2e-7,
                  "r=" + std::to_string(r) + " eps=" + std::to_string(eps));
      expect_near(shading::log_lobe_zh(8, r, eps), b, 2e-7, "dispatch");
    }
}

TEST(BrdfZh, LogDiffuseAndLogPhongMatchMathNotesTables) {
  const std::pair<double, sh::Vec> diffuse[] = {
      {0.01, {-11.908203, 4.545004, 1.258874, -1.004368}},
      {0.05, {-8.832816, 2.092712, 1.012390, -0.102150}},
      {0.10, {-7.325828, 1.085550, 0.719032, 0.180681}},
      {0.20, {-5.540424, 0.248822, 0.239844, 0.173368}},
      {0.50, {-2.457143, 0, 0, 0}},
  };
  for (const auto& [eps, zh] : diffuse)
    expect_near(shading::log_brdf_zh(4, Brdf{}, eps), zh, 2e-6, "log-diffuse eps=" + std::to_string(eps));
  // Diffuse z_0 = √π·(ln(ε/π) − 1 + πε) (math-notes §7).
  EXPECT_NEAR(shading::log_brdf_zh(4, Brdf{}, 0.1)[0], std::sqrt(kPi) * (std::log(0.1 / kPi) - 1 + kPi * 0.1), 1e-13);
  expect_near(shading::log_brdf_zh(4, Brdf{BrdfKind::Phong, 4.0}, 0.1), {-7.354725, 1.202093, 1.122644, 0.762205}, 2e-6,
              "log-Phong r=4");
  expect_near(shading::log_brdf_zh(4, Brdf{BrdfKind::Phong, 16.0}, 0.1), {-7.599366, 0.913692, 1.031746, 0.989129},
              2e-6, "log-Phong r=16");
}

TEST(BrdfZh, LogLobeIsConstantWhenEpsilonExceedsThePeak) {
  // ε ≥ (r+1)/(2π): ln max(g, ε) = ln ε everywhere (ε ≥ 1/π for diffuse).
  for (int order : {4, 6}) {
    const auto z = shading::log_lobe_zh(order, 1.0, 1.0 / kPi + 1e-9);
    EXPECT_NEAR(z[0], sh::kSqrt4Pi * std::log(1.0 / kPi + 1e-9), 1e-12);
    for (int l = 1; l < order; ++l) EXPECT_EQ(z[l], 0.0);
  }
}

TEST(BrdfZh, RejectsBadArguments) {
  EXPECT_THROW(shading::log_lobe_zh_closed_form(5, 1.0, 0.1), std::invalid_argument);
  EXPECT_THROW(shading::log_lobe_zh(4, 1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(shading::lobe_zh(4, 0.0), std::invalid_argument);
  EXPECT_THROW(shading::lobe_zh(sh::kMaxOrder + 1, 1.0), std::invalid_argument);
}

TEST(BrdfZh, LobeAxisIsNormalOrMirrorDirection) {
  const glm::dvec3 n = glm::normalize(glm::dvec3(0.2, -0.1, 1.0)), v = glm::normalize(glm::dvec3(-0.5, 0.3, 0.8));
  const glm::dvec3 a = shading::lobe_axis(Brdf{}, n, v);
  EXPECT_NEAR(glm::length(a - n), 0.0, 1e-15);
  const glm::dvec3 r = shading::lobe_axis(Brdf{BrdfKind::Phong, 8.0}, n, v);
  EXPECT_NEAR(glm::length(r), 1.0, 1e-14);
  EXPECT_NEAR(glm::dot(r, n), glm::dot(v, n), 1e-14);                    // equal angles to n
  EXPECT_NEAR(glm::dot(glm::cross(n, v), r), 0.0, 1e-14);                // in the plane of n and v
  EXPECT_NEAR(glm::length(r + v - 2 * glm::dot(n, v) * n), 0.0, 1e-14);  // r + v ∥ n
}
