// The k-means sphere fit on solids whose answer is known: one ball (K = 1 recovers its
// centre and radius) and a dumbbell (K = 2 puts a sphere on each lobe).
#include "flight/sphere_fit.h"
#include "flight/mesh_shapes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace skylit::flight {
namespace {

constexpr double kPi = std::numbers::pi;

FitOptions quick(int k, RadiusRule rule = RadiusRule::kHalfSolidShell) {
  FitOptions o;
  o.k = k;
  o.samples = 20000;
  o.error_samples = 200000;
  o.error_rays = 20000;
  o.radius_rule = rule;
  return o;
}

TEST(SphereFit, OneSphereRecoversABall) {
  const double r = 2.0;
  const glm::dvec3 c0(1.0, -0.5, 0.3);
  const Mesh ball = transformed(make_icosphere(r, 4), glm::dmat3(1.0), c0);
  for (RadiusRule rule : {RadiusRule::kHalfSolidShell, RadiusRule::kVolumeShare}) {
    const SphereFit fit = fit_spheres(ball, quick(1, rule));
    ASSERT_EQ(fit.spheres.size(), 1u);
    EXPECT_LT(glm::length(fit.spheres[0].centre - c0), 0.03);
    EXPECT_NEAR(fit.spheres[0].radius, r, 0.02 * r);
    EXPECT_LT(fit.report.volume.relative, 0.04);
    EXPECT_NEAR(fit.report.volume.volume_a, 4.0 / 3.0 * kPi * r * r * r, 0.02 * 4.0 / 3.0 * kPi * r * r * r);
    for (const auto& v : fit.report.views) EXPECT_LT(std::abs(v.relative()), 0.04) << v.view.label;
  }
}

TEST(SphereFit, PlanformSpheresCastAThinWingsShadow) {
  // A 12 m × 1 m × 0.12 m plate: seen from far below it subtends its area 12 m² / d².
  // K = 1: the planform disc has that area plus what the cells cut by the outline add,
  // at most one cell row along the perimeter (h = 2·cbrt(V/n), the rule's cell; with
  // 8t/h ≈ 11 points per cell no inner cell stays empty). K = 12: the discs cover it as seen from below
  // within 15 %, where the shell rule's balls of the plate's thickness miss most of it.
  const Mesh plate = make_box({-0.5, -6.0, -0.06}, {0.5, 6.0, 0.06});
  const FitOptions o1 = quick(1, RadiusRule::kPlanformArea);
  const SphereFit one = fit_spheres(plate, o1);
  ASSERT_EQ(one.spheres.size(), 1u);
  const double h = 2.0 * std::cbrt(1.44 / static_cast<double>(o1.samples));
  const double area = kPi * one.spheres[0].radius * one.spheres[0].radius;
  EXPECT_GE(area, 0.99 * 12.0);
  EXPECT_LE(area, 12.0 + 26.0 * h);
  auto from_below = [](const FitReport& r) {
    for (const auto& v : r.views)
      if (v.view.label.find("below") != std::string::npos) return v.relative();
    ADD_FAILURE() << "no view from below";
    return 0.0;
  };
  const SphereFit planform = fit_spheres(plate, quick(12, RadiusRule::kPlanformArea));
  EXPECT_LT(std::abs(from_below(planform.report)), 0.15);
  const SphereFit shell = fit_spheres(plate, quick(12, RadiusRule::kHalfSolidShell));
  EXPECT_LT(from_below(shell.report), -0.5);
}

TEST(SphereFit, TwoSpheresSitOnTheLobesOfADumbbell) {
  // Balls of radius 1 at x = ±3 joined by a rod of radius 0.2 along x. Each cluster is
  // one half; its centroid is pulled inward by the rod's 2 m outside the ball (centred at
  // |x| = 1): x = (V_ball·3 + V_rod·1) / (V_ball + V_rod).
  Mesh bell = transformed(make_icosphere(1.0, 4), glm::dmat3(1.0), {3, 0, 0});
  bell.append(transformed(make_icosphere(1.0, 4), glm::dmat3(1.0), {-3, 0, 0}));
  const glm::dmat3 z_to_x(glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0), glm::dvec3(1, 0, 0));  // columns: images of x, y, z
  bell.append(transformed(make_prism(0.2, 6.0, 32), z_to_x, {-3, 0, 0}));
  const double v_ball = 4.0 / 3.0 * kPi, v_rod = kPi * 0.04 * 2.0;
  const double expected_x = (v_ball * 3 + v_rod * 1) / (v_ball + v_rod);
  const SphereFit fit = fit_spheres(bell, quick(2));
  ASSERT_EQ(fit.spheres.size(), 2u);
  auto s = fit.spheres;
  std::sort(s.begin(), s.end(), [](const BodySphere& a, const BodySphere& b) { return a.centre.x < b.centre.x; });
  EXPECT_NEAR(s[0].centre.x, -expected_x, 0.05);
  EXPECT_NEAR(s[1].centre.x, expected_x, 0.05);
  for (const auto& sp : s) {
    EXPECT_NEAR(sp.centre.y, 0.0, 0.03);
    EXPECT_NEAR(sp.centre.z, 0.0, 0.03);
    EXPECT_NEAR(sp.radius, 1.0, 0.1);
  }
}

TEST(SphereFit, BadOptionsAndMeshes) {
  const Mesh ball = make_icosphere(1.0, 2);
  EXPECT_THROW(fit_spheres(ball, quick(0)), FitError);
  FitOptions few = quick(10);
  few.samples = 5;
  EXPECT_THROW(fit_spheres(ball, few), FitError);
  Mesh open = ball;
  open.triangles.pop_back();
  EXPECT_THROW(fit_spheres(open, quick(1)), MeshError);
}

TEST(SphereFit, SameSeedSameSpheres) {
  const Mesh ball = make_icosphere(1.0, 2);
  const auto a = fit_spheres(ball, quick(3)), b = fit_spheres(ball, quick(3));
  ASSERT_EQ(a.spheres.size(), b.spheres.size());
  for (std::size_t i = 0; i < a.spheres.size(); ++i) EXPECT_EQ(a.spheres[i].centre, b.spheres[i].centre);
}

}  // namespace
}  // namespace skylit::flight
