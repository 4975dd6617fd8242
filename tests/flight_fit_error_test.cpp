// The fit-error estimators against closed forms: the symmetric difference of two
// overlapping balls (lens volume) and the solid angle of a ball (a cap) seen from afar.
#include "flight/fit_error.h"
#include "flight/mesh_shapes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace skylit::flight {
namespace {

constexpr double kPi = std::numbers::pi;

// Two balls of radii R, r with centres d apart (|R − r| < d < R + r) meet in a lens of
// volume π (R + r − d)² (d² + 2dr − 3r² + 2dR + 6rR − 3R²) / (12 d) (the two caps' sum).
double lens_volume(double big_r, double r, double d) {
  return kPi * std::pow(big_r + r - d, 2) * (d * d + 2 * d * r - 3 * r * r + 2 * d * big_r + 6 * r * big_r - 3 * big_r * big_r) /
         (12 * d);
}

TEST(LensVolume, MatchesTheEqualBallsForm) {
  // Equal radii: π (4R + d)(2R − d)² / 12.
  EXPECT_NEAR(lens_volume(1, 1, 0.6), kPi * (4 + 0.6) * 1.4 * 1.4 / 12, 1e-12);
}

TEST(CompareVolumes, SymmetricDifferenceOfTwoBallsIsTheirVolumesLessTwoLenses) {
  const double ra = 1.0, rb = 0.8, d = 1.2;
  const BodySphere a{{0, 0, 0}, ra}, b{{d, 0, 0}, rb};
  const VolumeComparison c = compare_volumes([&](const glm::dvec3& p) { return inside_any({a}, p); },
                                             [&](const glm::dvec3& p) { return inside_any({b}, p); },
                                             bounds(std::vector<BodySphere>{a, b}), 400000, 11);
  const double va = 4.0 / 3.0 * kPi * ra * ra * ra, vb = 4.0 / 3.0 * kPi * rb * rb * rb;
  const double expected = va + vb - 2 * lens_volume(ra, rb, d);
  EXPECT_NEAR(c.volume_a, va, 4 * c.volume_a_se);
  EXPECT_NEAR(c.volume_b, vb, 4 * c.volume_b_se);
  EXPECT_NEAR(c.symmetric_difference, expected, 4 * c.symmetric_difference_se);
  EXPECT_NEAR(c.relative, expected / va, 4 * c.relative_se);
  EXPECT_LT(c.symmetric_difference_se, 0.01 * expected);  // the stated error is small and not zero
  EXPECT_GT(c.relative_se, 0.0);
}

TEST(CompareSolidAngles, BallAndIcosphereSubtendTheirCaps) {
  // A ball of radius r at distance D blocks the cap 2π (1 − √(1 − (r/D)²)).
  const Mesh ico = make_icosphere(1.0, 4);
  const std::vector<BodySphere> spheres{{{0, 3, 0}, 1.0}};
  const Viewpoint view{"below", {0, 0, -10}};
  const SolidAngleComparison c = compare_solid_angles(ico, spheres, view, 400000, 5);
  auto cap = [](double r, double dist) { return 2 * kPi * (1 - std::sqrt(1 - (r / dist) * (r / dist))); };
  const double ball_sr = cap(1.0, std::sqrt(109.0)), ico_sr = cap(1.0, 10.0);
  EXPECT_NEAR(c.spheres_sr, ball_sr, 0.015 * ball_sr);  // ≈ 4 standard errors
  EXPECT_NEAR(c.mesh_sr, ico_sr, 0.02 * ico_sr);  // inscribed: slightly less than the ball
  // The two solids do not overlap in direction, so every ray blocked by one is a mismatch
  // and the difference is the difference of the caps.
  EXPECT_NEAR(c.mismatch_sr, c.mesh_sr + c.spheres_sr, 1e-15);
  EXPECT_NEAR(c.difference_sr, ball_sr - ico_sr, 4 * c.difference_se_sr + 0.005 * ico_sr);
  EXPECT_GT(c.difference_se_sr, 0.0);
  EXPECT_THROW(compare_solid_angles(ico, spheres, {"inside", {0, 0, 0}}, 10, 1), MeshError);
}

}  // namespace
}  // namespace skylit::flight
