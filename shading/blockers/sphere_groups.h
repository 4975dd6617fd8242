// Spheres grouped into aircraft-sized clusters, each the root of a sphere tree (DESIGN.md
// "Aircraft"): a receiver that sees a node's bounding sphere under a small angle takes
// the node's spheres as one cap (their areas summed: log*(V_cap) is linear in (r/d)² for
// small caps, and with the centroid weighted by r² the first-order errors of distance
// and direction cancel), else looks at its two children. Ten aircraft far away cost ten
// caps, not 300, and an aircraft 150 m up costs its receivers below a handful of parts.
#pragma once

#include "shading/blockers/sphere_blocker.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

namespace skylit::blockers {

// Spheres whose centres lie within this of a group's first sphere join it (m): an
// aircraft of up to ~80 m is one group.
inline constexpr double kGroupSpan = 40.0;

// A node of a group's tree: the spheres order[first, first + count) (a node's children
// split its range in two), summarised.
struct SphereGroup {
  glm::dvec3 centre{0.0};    // the members' centroid, weighted by r²
  double bound = 0.0;        // radius about centre that holds every member
  double area = 0.0;         // Σ r² (m²)
  std::uint32_t first = 0, count = 0;  // members: SphereGroups::order[first, first + count)
  // The index in SphereGroups::nodes just past this node's subtree; a node with
  // children (count > 1) has its first child at the next index.
  std::uint32_t next = 0;
};

struct SphereGroups {
  std::vector<SphereGroup> nodes;    // each group's tree in pre-order, group after group
  std::vector<std::uint32_t> roots;  // group g's tree: nodes[roots[g], group(g).next)
  std::vector<std::uint32_t> order;  // sphere indices, group by group
  std::size_t size() const { return roots.size(); }
  const SphereGroup& group(std::size_t g) const { return nodes[roots[g]]; }
};

// Greedy, in input order: each sphere joins the first group whose first sphere lies
// within `span`, or starts one. A group's tree halves each node at the median of its
// centres along their longest extent, down to single spheres.
SphereGroups group_spheres(std::span<const Sphere> spheres, double span = kGroupSpan);

// Whether a receiver at distance d from a node's centre takes it as one cap:
// bound ≤ merge_sin · d (merge_sin 0: never).
inline bool seen_as_one(const SphereGroup& g, double d, double merge_sin) { return g.bound <= merge_sin * d; }

// A node as one sphere for the cap: at its centre, of radius √area (the cap's r/d), but
// no larger than its bound, which holds the members' union (overlapping members would
// sum to more); `bound` itself serves the tangent-plane and horizon culls.
inline Sphere equivalent_sphere(const SphereGroup& g) { return {g.centre, std::min(std::sqrt(g.area), g.bound)}; }

// Any node may be one cap (for_each_cap's default).
struct AnyNode {
  bool operator()(const SphereGroup&, const Sphere&) const { return true; }
};

// Calls cap(sphere, extent) for the caps a receiver at `position` takes from group g:
// each node it sees as one and may_merge(node, its bound) allows (its equivalent sphere,
// bounded by its bound), else the node's children, down to single spheres (sphere and
// extent the same).
template <class Cap, class MayMerge = AnyNode>
void for_each_cap(std::span<const Sphere> spheres, const SphereGroups& groups, std::uint32_t g,
                  const glm::dvec3& position, double merge_sin, Cap&& cap, MayMerge may_merge = {}) {
  const std::uint32_t end = groups.group(g).next;
  for (std::uint32_t n = groups.roots[g]; n < end;) {
    const SphereGroup& node = groups.nodes[n];
    if (node.count == 1) {
      const Sphere& s = spheres[groups.order[node.first]];
      cap(s, s);
    } else if (const Sphere extent{node.centre, node.bound};
               seen_as_one(node, glm::length(node.centre - position), merge_sin) && may_merge(node, extent)) {
      cap(equivalent_sphere(node), extent);
    } else {
      ++n;  // its children
      continue;
    }
    n = node.next;
  }
}

}  // namespace skylit::blockers
