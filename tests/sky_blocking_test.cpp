// blockers::horizon_side against its definition sampled densely over the cap, and
// for_each_cap's merge veto: a node across the horizon is taken as its members.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "shading/blockers/sky_blocking.h"

namespace skylit::blockers {
namespace {

constexpr double kPi = std::numbers::pi;

// The sphere of angular radius `half` whose centre is at elevation `elevation` and math
// azimuth `azimuth`, seen from the origin at distance d.
Sphere seen_at(double azimuth, double elevation, double half, double d = 100.0) {
  const glm::dvec3 dir(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                       std::sin(elevation));
  return {d * dir, d * std::sin(half)};
}

Receiver receiver(const std::vector<double>& sigma) { return {glm::dvec3(0.0), glm::dvec3(0, 0, 1), sigma, {}, {}}; }

TEST(HorizonSide, AgainstAFlatHorizon) {
  const std::vector<double> sigma(32, 0.1);
  const Receiver r = receiver(sigma);
  EXPECT_EQ(horizon_side(seen_at(1.0, 0.3, 0.05), r), HorizonSide::kAbove);
  EXPECT_EQ(horizon_side(seen_at(1.0, 0.0, 0.05), r), HorizonSide::kBelow);
  EXPECT_EQ(horizon_side(seen_at(1.0, 0.1, 0.05), r), HorizonSide::kAcross);
  EXPECT_EQ(horizon_side(seen_at(1.0, 0.16, 0.05), r), HorizonSide::kAbove);
  EXPECT_EQ(horizon_side(seen_at(1.0, 0.04, 0.05), r), HorizonSide::kBelow);
  // Wider than a quarter turn: never below; above only over every sample.
  EXPECT_EQ(horizon_side(seen_at(1.0, -0.5, 1.0), r), HorizonSide::kAcross);
  EXPECT_EQ(horizon_side(seen_at(1.0, 1.2, 1.0), r), HorizonSide::kAbove);
  // The receiver inside the sphere; no horizons at all.
  EXPECT_EQ(horizon_side({glm::dvec3(0.5, 0, 0), 1.0}, r), HorizonSide::kAcross);
  EXPECT_EQ(horizon_side(seen_at(1.0, -0.5, 0.05), receiver({})), HorizonSide::kAbove);
}

TEST(HorizonSide, ConservativeAgainstTheCapSampledDensely) {
  // Random horizons and spheres: where it says below, every direction of the cap lies
  // under the horizon samples on both sides of its azimuth; where above, over both.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int w = 32;
  int counts[3] = {0, 0, 0};
  for (int trial = 0; trial < 3000; ++trial) {
    std::vector<double> sigma(w);
    const double base = -0.3 + 0.6 * u(rng);
    for (double& s : sigma) s = base + 0.3 * (u(rng) - 0.5);
    const Receiver r = receiver(sigma);
    const double half = 0.001 + 0.2 * u(rng) * u(rng);
    const Sphere s = seen_at(2 * kPi * u(rng), base + 0.5 * (u(rng) - 0.5), half);
    const HorizonSide side = horizon_side(s, r);
    ++counts[static_cast<int>(side)];
    if (side == HorizonSide::kAcross) continue;
    const glm::dvec3 axis = glm::normalize(s.centre);
    const glm::dvec3 e1 = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), axis)), e2 = glm::cross(axis, e1);
    for (int a = 0; a < 64; ++a)
      for (int b = 1; b <= 8; ++b) {
        const double t = half * b / 8.0, phi = 2 * kPi * a / 64.0;
        const glm::dvec3 d = std::cos(t) * axis + std::sin(t) * (std::cos(phi) * e1 + std::sin(phi) * e2);
        const double el = std::asin(d.z), az = std::atan2(d.y, d.x);
        const double x = az / (2 * kPi / w);
        const int k0 = static_cast<int>(std::floor(x)), k1 = k0 + 1;
        const double h0 = sigma[((k0 % w) + w) % w], h1 = sigma[((k1 % w) + w) % w];
        if (side == HorizonSide::kBelow) {
          ASSERT_LT(el, std::min(h0, h1)) << trial;
        } else {
          ASSERT_GE(el, std::max(h0, h1) - 1e-12) << trial;
        }
      }
  }
  std::printf("3000 spheres: %d above, %d below, %d across\n", counts[0], counts[1], counts[2]);
  for (int c : counts) EXPECT_GT(c, 300);
}

TEST(ForEachCap, ANodeItMayNotMergeIsTakenAsItsMembers) {
  std::vector<Sphere> spheres;
  for (int k = 0; k < 16; ++k) spheres.push_back({glm::dvec3(k * 2.0, 0, 500), 1.0});
  const SphereGroups groups = group_spheres(spheres);
  ASSERT_EQ(groups.size(), 1u);
  int merged = 0, vetoed = 0;
  for_each_cap(spheres, groups, 0, glm::dvec3(0.0), 0.5, [&](const Sphere&, const Sphere&) { ++merged; });
  for_each_cap(
      spheres, groups, 0, glm::dvec3(0.0), 0.5, [&](const Sphere&, const Sphere&) { ++vetoed; },
      [](const SphereGroup&, const Sphere&) { return false; });
  EXPECT_EQ(merged, 1);
  EXPECT_EQ(vetoed, 16);
}

}  // namespace
}  // namespace skylit::blockers
