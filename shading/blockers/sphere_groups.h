// Spheres grouped into aircraft-sized clusters, a two-level sphere tree (DESIGN.md
// "Aircraft"): a receiver that sees a group's bounding sphere under a small angle takes
// the whole group as one cap (its members' areas summed: log*(V_cap) is linear in
// (r/d)² for small caps, and with the centroid weighted by r² the first-order errors of
// distance and direction cancel), so ten aircraft cost ten caps there, not 300.
#pragma once

#include "shading/blockers/sphere_blocker.h"

#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

namespace skylit::blockers {

// Spheres whose centres lie within this of a group's first sphere join it (m): an
// aircraft of up to ~80 m is one group.
inline constexpr double kGroupSpan = 40.0;

struct SphereGroup {
  glm::dvec3 centre{0.0};    // the members' centroid, weighted by r²
  double bound = 0.0;        // radius about centre that holds every member
  double area = 0.0;         // Σ r² (m²)
  std::uint32_t first = 0, count = 0;  // members: SphereGroups::order[first, first + count)
};

struct SphereGroups {
  std::vector<SphereGroup> groups;
  std::vector<std::uint32_t> order;  // sphere indices, group by group
};

// Greedy, in input order: each sphere joins the first group whose first sphere lies
// within `span`, or starts one.
SphereGroups group_spheres(std::span<const Sphere> spheres, double span = kGroupSpan);

// Whether a receiver at distance d from the group's centre takes it as one cap:
// bound ≤ merge_sin · d (merge_sin 0: never).
inline bool seen_as_one(const SphereGroup& g, double d, double merge_sin) { return g.bound <= merge_sin * d; }

// The group as one sphere for the culls and the cap: at its centre, of radius √area
// (the cap's r/d), bounded by `bound` (the tangent-plane and horizon culls).
inline Sphere equivalent_sphere(const SphereGroup& g) { return {g.centre, std::sqrt(g.area)}; }

}  // namespace skylit::blockers
