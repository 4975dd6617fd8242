#include "shading/blockers/sphere_groups.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace skylit::blockers {

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
    SphereGroup g;
    g.first = static_cast<std::uint32_t>(out.order.size());
    g.count = static_cast<std::uint32_t>(m.size());
    glm::dvec3 weighted(0.0);
    for (std::uint32_t k : m) {
      const double a = spheres[k].radius * spheres[k].radius;
      g.area += a;
      weighted += a * spheres[k].centre;
    }
    g.centre = weighted / g.area;
    for (std::uint32_t k : m) g.bound = std::max(g.bound, glm::length(spheres[k].centre - g.centre) + spheres[k].radius);
    out.order.insert(out.order.end(), m.begin(), m.end());
    out.groups.push_back(g);
  }
  return out;
}

}  // namespace skylit::blockers
