// The budget per receiver (shading/blockers/receiver_budget.h): a node's cull bound holds
// the sum of its members' bounds n·Ω/(4π) (brute force over the members, every node of
// aircraft, a fleet, coincident and scattered spheres, from 4 bounds out) and is tight
// far away; beyond node_reach it is under the share; drop_smallest drops the longest run
// of the smallest bounds that fits the budget (against a sort).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "sphere_sets.h"
#include "shading/blockers/receiver_budget.h"
#include "shading/sh/zonal.h"

namespace skylit::blockers {
namespace {

using test::airliner;
const auto cases = test::sphere_cases;

// Σ n·Ω_i/(4π) over the node's members seen from p: what the size cull bounds per sphere.
double members_bound(const std::vector<Sphere>& spheres, const SphereGroups& g, const SphereGroup& node,
                     const glm::dvec3& p, int order) {
  double sum = 0.0;
  for (std::uint32_t m = node.first; m < node.first + node.count; ++m) {
    const Sphere& s = spheres[g.order[m]];
    sum += order * sh::cap_solid_angle(sphere_cap_cos(s.radius, glm::length(s.centre - p))) / (4.0 * sh::kPi);
  }
  return sum;
}

glm::dvec3 random_direction(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return glm::normalize(glm::dvec3(n(rng), n(rng), n(rng)));
}

TEST(ReceiverBudget, NodeBoundHoldsItsMembersAndIsTightFarAway) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst_far = 1.0;
  int checked = 0;
  for (const auto& spheres : cases()) {
    const SphereGroups g = group_spheres(spheres);
    for (const SphereGroup& node : g.nodes)
      for (int order : {3, 4, 6})
        for (int t = 0; t < 40; ++t) {
          // From just outside kNearBounds bounds to 200 bounds away (and 1 m for a point).
          const double reach = std::max(node.bound, 1.0) * kNearBounds * (1.0 + 1e-9 + 50.0 * u(rng) * u(rng));
          const glm::dvec3 dir = random_direction(rng);
          const glm::dvec3 p = node.centre - reach * dir;
          const double bound = node_cull_bound(node, p, dir, order);  // normal toward it: never below the plane
          const double exact = members_bound(spheres, g, node, p, order);
          ASSERT_TRUE(std::isfinite(bound));
          EXPECT_GE(bound, exact * (1.0 - 1e-12)) << node.count << " members, d/R " << reach / node.bound;
          if (reach >= 20.0 * node.bound) worst_far = std::max(worst_far, bound / exact);
          ++checked;
        }
  }
  std::printf("%d checks; far away (d ≥ 20 R) the bound is within %.4f of the members' sum\n", checked, worst_far);
  EXPECT_LT(worst_far, 1.02);
}

TEST(ReceiverBudget, NodeBoundIsZeroBelowThePlaneAndUnboundedNear) {
  const SphereGroups g = group_spheres(airliner({0, 0, 0}));
  const SphereGroup& root = g.group(0);
  EXPECT_EQ(node_cull_bound(root, root.centre + glm::dvec3(0, 0, root.bound + 1.0), {0, 0, 1}, 4), 0.0);
  EXPECT_EQ(node_cull_bound(root, root.centre + glm::dvec3(0, 0, 3.9 * root.bound), {0, 0, -1}, 4),
            std::numeric_limits<double>::infinity());
}

TEST(ReceiverBudget, BeyondTheReachTheBoundIsUnderTheShare) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double loosest = 0.0;
  for (const auto& spheres : cases()) {
    const SphereGroups g = group_spheres(spheres);
    for (const SphereGroup& node : g.nodes)
      for (double share : {1e-7, 1e-4, 1e-3, 0.05, 0.5}) {
        const double reach = node_reach(node, 4, share);
        for (int t = 0; t < 20; ++t) {
          const glm::dvec3 dir = random_direction(rng);
          const double d = reach * (1.0 + 2.0 * u(rng) * u(rng));
          EXPECT_LE(node_cull_bound(node, node.centre - d * dir, dir, 4), share) << node.count << " " << share;
        }
        // Not loose by much where the reach is √(nA/4s) + R (not kNearBounds·R): the bound
        // there against the share, at most ((d₀ + R)/d₀)² ≤ (4/3)² with d₀ ≥ 3R.
        if (reach > kNearBounds * node.bound)
          loosest = std::max(loosest, share / node_cull_bound(node, node.centre - glm::dvec3(0, 0, reach), {0, 0, 1}, 4));
      }
  }
  std::printf("at the reach the bound is at least 1/%.2f of the share\n", loosest);
  EXPECT_LT(loosest, 16.0 / 9.0);
}

TEST(ReceiverBudget, DropsTheLongestRunOfTheSmallestThatFits) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double inf = std::numeric_limits<double>::infinity();
  for (int t = 0; t < 2000; ++t) {
    const std::size_t k = 1 + rng() % 40;
    std::vector<double> bounds(k);
    for (double& b : bounds) {
      const double x = u(rng);
      b = x < 0.1 ? 0.0 : x < 0.15 ? inf : x < 0.3 ? 2e-4 : 1e-3 * u(rng);  // zeros, ∞ and ties
    }
    const double budget = 1e-3 * (0.2 + 2.0 * u(rng));
    std::array<bool, 64> store{};
    const std::span<bool> dropped(store.data(), k);
    drop_smallest(bounds, budget, dropped);
    double sum = 0.0;
    for (std::size_t q = 0; q < k; ++q) sum += dropped[q] ? bounds[q] : 0.0;
    EXPECT_LE(sum, budget);
    if (k > static_cast<std::size_t>(kMaxRankedGroups)) {
      for (std::size_t q = 0; q < k; ++q) EXPECT_EQ(dropped[q], bounds[q] <= budget / k);
      continue;
    }
    // Against a stable sort: drop while the running sum fits.
    std::vector<std::size_t> idx(k);
    std::iota(idx.begin(), idx.end(), 0);
    std::stable_sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return bounds[a] < bounds[b]; });
    double run = 0.0;
    for (std::size_t q : idx) {
      run += bounds[q];
      EXPECT_EQ(dropped[q], run <= budget) << t << " " << q;
    }
  }
}

}  // namespace
}  // namespace skylit::blockers
