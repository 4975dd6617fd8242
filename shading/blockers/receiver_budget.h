// The size cull as a budget per receiver (DESIGN.md "Aircraft"): a receiver drops the
// sphere groups (aircraft) whose cull bounds add up to at most the budget, the smallest
// first, and keeps every part of the others. What it drops can change its visibility by
// at most the budget, however many aircraft a frame holds: a frame-wide share (budget/N
// per aircraft) made each of ten aircraft reach √10 times as far.
#pragma once

#include "shading/blockers/sphere_groups.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <span>

namespace skylit::blockers {

// Nodes nearer than this many bounds are never dropped (the bound below needs them far).
inline constexpr double kNearBounds = 4.0;
// The most candidate groups a receiver ranks; with more, each is dropped only when its
// bound is at most budget/k (the same guarantee, less dropped).
inline constexpr int kMaxRankedGroups = 32;

// An upper bound on the members' summed cull bounds n·Ω_i/(4π) (sphere_blocker.h: what
// a cap can change), seen from p with unit normal `normal` at SH order n: 0 for a node
// wholly below the tangent plane, +∞ within kNearBounds bounds R of its centre, else
//   (n/4)·(A/d²)·(1 + (ρ(2 + ρ)/(1 − ρ))²)/√(1 − σ²),  ρ = R/d, σ = ρ/(1 − ρ),
// A = Σr², d the distance to the r²-weighted centre (docs/accuracy.md derives it).
double node_cull_bound(const SphereGroup& node, const glm::dvec3& p, const glm::dvec3& normal, int order);

// The distance from a node's centre beyond which its cull bound is at most `share`
// (kNearBounds bounds at least; +∞ for share 0): a bin lists the group within it.
double node_reach(const SphereGroup& node, int order, double share);

// The bound under which a bin leaves a group out (node_reach's share): budget/N of a
// frame's N groups, since a receiver ranking k ≤ N drops any group that small.
inline double unlisted_share(double budget, std::size_t n) {
  return n == 0 ? budget : budget / static_cast<double>(n);
}

// What is left of a receiver's budget for the k groups its bin lists out of a frame's N:
// the N − k unlisted may take unlisted_share each, which leaves budget·k/N.
inline double listed_budget(double budget, std::size_t k, std::size_t n) {
  return n == 0 ? budget : budget * static_cast<double>(k) / static_cast<double>(n);
}

// Whether one of k > kMaxRankedGroups candidates is dropped: its bound ≤ budget/k.
inline bool drop_unranked(double bound, double budget, std::size_t k) { return bound <= budget / static_cast<double>(k); }

// dropped[q] for the candidates' bounds: whether bounds[q] and those sorted before it
// (smaller, or equal and earlier in the list) add up to at most `budget` (for more than
// kMaxRankedGroups: drop_unranked). The dropped bounds then add up to at most the
// budget, and they are the longest such run of the smallest. No allocation.
void drop_smallest(std::span<const double> bounds, double budget, std::span<bool> dropped);

}  // namespace skylit::blockers
