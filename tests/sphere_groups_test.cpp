// Sphere trees (shading/blockers/sphere_groups.h): every node bounds its members and
// sums their areas, children split their parent's members, and a receiver takes every
// sphere exactly once, as itself or inside one merged cap — checked against the spheres
// directly, for aircraft, coincident spheres and scattered ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "sphere_sets.h"
#include "shading/blockers/sphere_groups.h"

namespace skylit::blockers {
namespace {

using test::airliner;
const auto cases = test::sphere_cases;

TEST(SphereGroups, NodesBoundAndSumTheirMembersAndChildrenSplitThem) {
  for (const auto& spheres : cases()) {
    const SphereGroups groups = group_spheres(spheres);
    std::vector<int> seen(spheres.size(), 0);
    for (std::uint32_t k : groups.order) ++seen[k];
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; })) << "order is a permutation";
    for (std::size_t n = 0; n < groups.nodes.size(); ++n) {
      const SphereGroup& node = groups.nodes[n];
      ASSERT_GE(node.count, 1u);
      ASSERT_GT(node.next, n);
      double area = 0.0;
      for (std::uint32_t m = node.first; m < node.first + node.count; ++m) {
        const Sphere& s = spheres[groups.order[m]];
        area += s.radius * s.radius;
        EXPECT_LE(glm::length(s.centre - node.centre) + s.radius, node.bound * (1 + 1e-12) + 1e-12);
      }
      EXPECT_NEAR(node.area, area, 1e-12 * area);
      if (node.count == 1) {
        EXPECT_EQ(node.next, n + 1) << "a single sphere is a leaf";
        continue;
      }
      // The children, in pre-order from n + 1, tile the node's members and its subtree.
      const SphereGroup& a = groups.nodes[n + 1];
      ASSERT_LT(a.next, node.next);
      const SphereGroup& b = groups.nodes[a.next];
      EXPECT_EQ(a.first, node.first);
      EXPECT_EQ(b.first, a.first + a.count);
      EXPECT_EQ(a.count + b.count, node.count);
      EXPECT_EQ(b.next, node.next);
      EXPECT_LE(std::max(a.count, b.count), node.count - node.count / 2) << "halved";
    }
  }
}

TEST(SphereGroups, AReceiverTakesEverySphereOnceAsItselfOrMerged) {
  for (const auto& spheres : cases()) {
    const SphereGroups groups = group_spheres(spheres);
    for (const glm::dvec3 receiver : {glm::dvec3(0, 0, 0), glm::dvec3(200, 50, 0), glm::dvec3(5000, 0, 0)}) {
      for (double merge_sin : {0.0, 0.04, 0.5}) {
        double area = 0.0, total = 0.0;
        int caps = 0, alone = 0;
        for (std::uint32_t g = 0; g < groups.size(); ++g)
          for_each_cap(spheres, groups, g, receiver, merge_sin, [&](const Sphere& s, const Sphere& extent) {
            ++caps;
            area += s.radius * s.radius;
            if (s.centre == extent.centre && s.radius == extent.radius) {
              ++alone;
              return;
            }
            // A merged cap: seen within asin(merge_sin), no larger than its bound.
            EXPECT_LE(extent.radius, merge_sin * glm::length(extent.centre - receiver) * (1 + 1e-12));
            EXPECT_LT(s.radius, extent.radius);
          });
        for (const Sphere& s : spheres) total += s.radius * s.radius;
        // Every sphere's area once, where no node's members sum to more than its bound
        // (overlapping members: the cap is the bound's).
        bool overlapping = false;
        for (const SphereGroup& node : groups.nodes) overlapping |= std::sqrt(node.area) > node.bound;
        if (!overlapping) {
          EXPECT_NEAR(area, total, 1e-9 * total) << "every sphere's area once";
        } else {
          EXPECT_LE(area, total * (1 + 1e-12));
        }
        if (merge_sin == 0.0) {
          EXPECT_EQ(alone, static_cast<int>(spheres.size()));
        }
        EXPECT_GE(caps, static_cast<int>(groups.size()));
      }
    }
    // Far enough away, each group is one cap.
    int caps = 0;
    for (std::uint32_t g = 0; g < groups.size(); ++g)
      for_each_cap(spheres, groups, g, glm::dvec3(1e7, 0, 0), 0.04, [&](const Sphere&, const Sphere&) { ++caps; });
    EXPECT_EQ(caps, static_cast<int>(groups.size()));
  }
}

TEST(SphereGroups, AnAircraft150mUpIsAHandfulOfCapsFromTheGround) {
  // The point of the tree: receivers below a 35 m airliner take its wing and fuselage
  // parts, not its 30 spheres (the old two-level groups took all 30 within ~360 m).
  const auto spheres = airliner({0, 0, 150});
  const SphereGroups groups = group_spheres(spheres);
  ASSERT_EQ(groups.size(), 1u);
  for (double x : {0.0, 100.0, 200.0}) {
    int caps = 0;
    for_each_cap(spheres, groups, 0, glm::dvec3(x, 30, 0), 0.04, [&](const Sphere&, const Sphere&) { ++caps; });
    std::printf("airliner 150 m up, receiver %g m along: %d caps\n", x, caps);
    EXPECT_LE(caps, 8);
  }
}

}  // namespace
}  // namespace skylit::blockers
