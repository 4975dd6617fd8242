#include "shading/blockers/sphere_groups.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace skylit::blockers {
namespace {

SphereGroup summarise(std::span<const Sphere> spheres, std::span<const std::uint32_t> order, std::uint32_t first,
                      std::uint32_t count) {
  SphereGroup g;
  g.first = first;
  g.count = count;
  glm::dvec3 weighted(0.0);
  for (std::uint32_t m = first; m < first + count; ++m) {
    const Sphere& s = spheres[order[m]];
    g.area += s.radius * s.radius;
    weighted += s.radius * s.radius * s.centre;
  }
  g.centre = weighted / g.area;
  for (std::uint32_t m = first; m < first + count; ++m) {
    const Sphere& s = spheres[order[m]];
    g.bound = std::max(g.bound, glm::length(s.centre - g.centre) + s.radius);
  }
  return g;
}

// Appends the subtree of order[first, first + count) in pre-order; reorders that range.
void add_tree(std::span<const Sphere> spheres, SphereGroups& out, std::uint32_t first, std::uint32_t count) {
  const std::size_t at = out.nodes.size();
  out.nodes.push_back(summarise(spheres, out.order, first, count));
  if (count > 1) {
    glm::dvec3 lo = spheres[out.order[first]].centre, hi = lo;
    for (std::uint32_t m = first; m < first + count; ++m) {
      lo = glm::min(lo, spheres[out.order[m]].centre);
      hi = glm::max(hi, spheres[out.order[m]].centre);
    }
    const glm::dvec3 extent = hi - lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const auto begin = out.order.begin() + first;
    // Ties by index: the tree is a function of the spheres alone.
    std::stable_sort(begin, begin + count, [&](std::uint32_t a, std::uint32_t b) {
      return spheres[a].centre[axis] < spheres[b].centre[axis];
    });
    const std::uint32_t half = count / 2;
    add_tree(spheres, out, first, half);
    add_tree(spheres, out, first + half, count - half);
  }
  out.nodes[at].next = static_cast<std::uint32_t>(out.nodes.size());
}

}  // namespace

SphereGroups group_spheres(std::span<const Sphere> spheres, double span) {
  std::vector<std::uint32_t> seed;                  // first sphere of each group
  std::vector<std::vector<std::uint32_t>> members;  // per group
  for (std::uint32_t k = 0; k < spheres.size(); ++k) {
    std::size_t g = 0;
    while (g < seed.size() && glm::length(spheres[k].centre - spheres[seed[g]].centre) > span) ++g;
    if (g == seed.size()) {
      seed.push_back(k);
      members.emplace_back();
    }
    members[g].push_back(k);
  }
  SphereGroups out;
  for (const auto& m : members) {
    const auto first = static_cast<std::uint32_t>(out.order.size());
    out.order.insert(out.order.end(), m.begin(), m.end());
    out.roots.push_back(static_cast<std::uint32_t>(out.nodes.size()));
    add_tree(spheres, out, first, static_cast<std::uint32_t>(m.size()));
  }
  return out;
}

}  // namespace skylit::blockers
