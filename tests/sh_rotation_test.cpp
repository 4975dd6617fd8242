// SH rotations: the general 3D rotation against pointwise evaluation at the
// rotated direction, composition, agreement with rotate_z and rotate_zh, band
// energy; rotate_z against the projection of f(φ − α).
#include "shading/sh/quadrature.h"
#include "shading/sh/sh_basis.h"
#include "shading/sh/sh_rotation.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace skylit;

namespace {

// The block entries are exact quadratures: rounding only, for O(1) vectors.
constexpr double kRotationTol = 1e-12;

// Rodrigues: rotation by `angle` about unit `axis` (right-handed).
glm::dmat3 axis_angle(glm::dvec3 axis, double angle) {
  axis = glm::normalize(axis);
  const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
  const double x = axis.x, y = axis.y, z = axis.z;
  // glm is column-major: m[col][row].
  glm::dmat3 m;
  m[0] = {t * x * x + c, t * x * y + s * z, t * x * z - s * y};
  m[1] = {t * x * y - s * z, t * y * y + c, t * y * z + s * x};
  m[2] = {t * x * z + s * y, t * y * z - s * x, t * z * z + c};
  return m;
}

sh::Vec random_vector(int order, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  sh::Vec v(sh::num_coeffs(order));
  for (double& x : v) x = u(rng);
  return v;
}

glm::dvec3 random_direction(std::mt19937& rng) {
  std::normal_distribution<double> g;
  return glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
}

}  // namespace

TEST(ShRotation, RotateThenEvaluateEqualsEvaluateAtInverseRotatedDirection) {
  std::mt19937 rng(7);
  for (int order : {1, 2, 4, 6, 8}) {
    for (int trial = 0; trial < 5; ++trial) {
      const auto r = axis_angle(random_direction(rng), 0.3 + 1.1 * trial);
      const auto f = random_vector(order, rng);
      const auto g = sh::rotate(f, r);
      for (int k = 0; k < 10; ++k) {
        const auto d = random_direction(rng);
        // g(R·d) = f(d).
        EXPECT_NEAR(sh::reconstruct(g, r * d), sh::reconstruct(f, d), kRotationTol) << "order " << order;
      }
    }
  }
}

TEST(ShRotation, AboutZEqualsRotateZ) {
  std::mt19937 rng(3);
  for (double alpha : {-2.0, 0.4, 1.7, 3.0}) {
    const auto f = random_vector(8, rng);
    const auto general = sh::rotate(f, axis_angle({0, 0, 1}, alpha));
    const auto about_z = sh::rotate_z(f, alpha);
    for (std::size_t i = 0; i < f.size(); ++i) EXPECT_NEAR(general[i], about_z[i], kRotationTol);
  }
}

TEST(ShRotation, ComposesAndInvertsAndKeepsBandEnergy) {
  std::mt19937 rng(11);
  const auto r1 = axis_angle(random_direction(rng), 0.9), r2 = axis_angle(random_direction(rng), -2.2);
  const auto f = random_vector(7, rng);
  const auto two_steps = sh::rotate(sh::rotate(f, r1), r2);
  const auto one_step = sh::rotate(f, r2 * r1);
  const auto back = sh::rotate(one_step, glm::transpose(r2 * r1));
  for (std::size_t i = 0; i < f.size(); ++i) {
    EXPECT_NEAR(two_steps[i], one_step[i], kRotationTol);
    EXPECT_NEAR(back[i], f[i], kRotationTol);
  }
  for (int l = 0; l < 7; ++l) {
    double e0 = 0, e1 = 0;
    for (int m = -l; m <= l; ++m) {
      e0 += f[sh::index(l, m)] * f[sh::index(l, m)];
      e1 += one_step[sh::index(l, m)] * one_step[sh::index(l, m)];
    }
    EXPECT_NEAR(e0, e1, kRotationTol) << "band " << l;
  }
  // Each block is orthogonal.
  const sh::ShRotation rot(7, r1);
  for (int l = 0; l < 7; ++l) {
    const auto b = rot.band(l);
    const int w = 2 * l + 1;
    for (int i = 0; i < w; ++i)
      for (int j = 0; j < w; ++j) {
        double s = 0;
        for (int k = 0; k < w; ++k) s += b[k * w + i] * b[k * w + j];
        EXPECT_NEAR(s, i == j ? 1.0 : 0.0, kRotationTol);
      }
  }
}

TEST(ShRotation, ZonalVectorRotatedTowardAxisEqualsRotateZh) {
  std::mt19937 rng(5);
  for (int order : {2, 4, 8}) {
    sh::Vec zh(order), zh_full(sh::num_coeffs(order), 0.0);
    for (int l = 0; l < order; ++l) zh_full[sh::index(l, 0)] = zh[l] = 1.0 / (1 + l) - 0.3 * l;
    for (int trial = 0; trial < 4; ++trial) {
      const auto axis = random_direction(rng);
      // A rotation taking +z to axis: about z × axis by the angle between them.
      const glm::dvec3 z(0, 0, 1);
      const glm::dvec3 c = glm::cross(z, axis);
      const auto r = glm::length(c) < 1e-12 ? glm::dmat3(1.0) : axis_angle(c, std::acos(glm::dot(z, axis)));
      ASSERT_NEAR(glm::length(r * z - axis), 0.0, 1e-14);
      const auto general = sh::rotate(zh_full, r);
      const auto addition = sh::rotate_zh(zh, axis);
      for (std::size_t i = 0; i < general.size(); ++i) EXPECT_NEAR(general[i], addition[i], kRotationTol);
    }
  }
}

TEST(ShRotation, ApplyInPlaceMatchesCopyAndRejectsNonRotations) {
  std::mt19937 rng(9);
  const sh::ShRotation rot(5, axis_angle({1, 2, 3}, 0.7));
  auto f = random_vector(5, rng);
  const auto copy = rot.apply(f);
  rot.apply(f, f);
  for (std::size_t i = 0; i < f.size(); ++i) EXPECT_EQ(f[i], copy[i]);
  EXPECT_THROW(sh::ShRotation(4, glm::dmat3(2.0)), std::invalid_argument);
  glm::dmat3 mirror(1.0);
  mirror[2][2] = -1.0;
  EXPECT_THROW(sh::ShRotation(4, mirror), std::invalid_argument);
  EXPECT_THROW(sh::ShRotation(9, glm::dmat3(1.0)), std::invalid_argument);
}

TEST(RotateZ, EqualsProjectionOfShiftedFunction) {
  std::mt19937 rng(13);
  const auto f = random_vector(6, rng);
  const double alpha = 0.83;
  const auto rule = sh::sphere_rule_for_order(6);
  const auto shifted = sh::project(6, rule, [&](const glm::dvec3& d) {
    const double phi = std::atan2(d.y, d.x) - alpha, rxy = std::hypot(d.x, d.y);
    return sh::reconstruct(f, {rxy * std::cos(phi), rxy * std::sin(phi), d.z});
  });
  const auto rotated = sh::rotate_z(f, alpha);
  for (std::size_t i = 0; i < f.size(); ++i) EXPECT_NEAR(rotated[i], shifted[i], kRotationTol);
}
