#include "shading/blockers/receiver_budget.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace skylit::blockers {

double node_cull_bound(const SphereGroup& node, const glm::dvec3& p, const glm::dvec3& normal, int order) {
  const glm::dvec3 to_c = node.centre - p;
  if (glm::dot(normal, to_c) + node.bound <= 0.0) return 0.0;
  const double d = glm::length(to_c);
  if (!(d > kNearBounds * node.bound)) return std::numeric_limits<double>::infinity();
  const double rho = node.bound / d, sigma = rho / (1.0 - rho);
  const double spread = rho * (2.0 + rho) / (1.0 - rho);
  return 0.25 * order * node.area / (d * d) * (1.0 + spread * spread) / std::sqrt((1.0 - sigma) * (1.0 + sigma));
}

double node_reach(const SphereGroup& node, int order, double share) {
  if (!(share > 0.0)) return std::numeric_limits<double>::infinity();
  // At d = √(nA/(4·share)) + R the bound is at most share: (d − R)²/d² ≤ 1/(1 + …)/√(…)
  // for ρ ≤ 1/kNearBounds (checked in tests/receiver_budget_test.cpp).
  return std::max(std::sqrt(0.25 * order * node.area / share) + node.bound, kNearBounds * node.bound);
}

void drop_smallest(std::span<const double> bounds, double budget, std::span<bool> dropped) {
  const std::size_t k = bounds.size();
  if (k > static_cast<std::size_t>(kMaxRankedGroups)) {
    for (std::size_t q = 0; q < k; ++q) dropped[q] = drop_unranked(bounds[q], budget, k);
    return;
  }
  for (std::size_t q = 0; q < k; ++q) {
    double below = 0.0;
    for (std::size_t h = 0; h < k; ++h)  // those sorted before q, ties in list order
      if (bounds[h] < bounds[q] || (bounds[h] == bounds[q] && h <= q)) below += bounds[h];
    dropped[q] = below <= budget;
  }
}

}  // namespace skylit::blockers
