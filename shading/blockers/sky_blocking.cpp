#include "shading/blockers/sky_blocking.h"

#include "shading/blockers/receiver_budget.h"
#include "shading/sh/sh_basis.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace skylit::blockers {

HorizonSide horizon_side(const Sphere& s, const Receiver& r) {
  const int w = static_cast<int>(r.sigma.size());
  if (w == 0) return HorizonSide::kAbove;
  const glm::dvec3 to_c = s.centre - r.position;
  const double d = glm::length(to_c);
  if (d <= s.radius) return HorizonSide::kAcross;
  const double half = std::asin(s.radius / d);
  const double horizontal = std::hypot(to_c.x, to_c.y);
  const double elevation = std::atan2(to_c.z, horizontal);
  const double top = elevation + half, bottom = elevation - half;
  // Azimuth half-width of the cap: asin(sin α / cos e) at the centre's elevation e.
  const double cos_e = horizontal / d;
  const double sin_half = std::sin(half);
  if (sin_half >= cos_e * std::sin(std::numbers::pi / 4)) {  // wider than a quarter turn
    return bottom >= *std::max_element(r.sigma.begin(), r.sigma.end()) ? HorizonSide::kAbove : HorizonSide::kAcross;
  }
  const double spread = std::asin(sin_half / cos_e);
  const double step = 2.0 * std::numbers::pi / w;
  const double phi = std::atan2(to_c.y, to_c.x);
  // Every sample from the one at or before phi − spread to the one at or after phi + spread.
  const int k0 = static_cast<int>(std::floor((phi - spread) / step));
  const int k1 = static_cast<int>(std::ceil((phi + spread) / step));
  double lowest = std::numbers::pi, highest = -std::numbers::pi;
  for (int k = k0; k <= k1; ++k) {
    const double sigma = r.sigma[((k % w) + w) % w];
    lowest = std::min(lowest, sigma);
    highest = std::max(highest, sigma);
  }
  if (top < std::numbers::pi / 2 && top < lowest) return HorizonSide::kBelow;
  return bottom >= highest ? HorizonSide::kAbove : HorizonSide::kAcross;
}

int block_sky(std::span<const Sphere> spheres, const SphereGroups& groups, std::span<const std::uint32_t> candidates,
              const Receiver& r, const SkyBlockingOptions& options, std::span<double> delta, std::span<double> log_sum,
              std::span<double> scratch) {
  const std::size_t size = delta.size();
  const int order = sh::order_of(size);
  const std::span<double> f_s = scratch.subspan(0, size), a = scratch.subspan(size, size),
                          b = scratch.subspan(2 * size, size);
  std::fill(f_s.begin(), f_s.end(), 0.0);
  std::array<double, sh::kMaxOrder> zh{};
  const std::span<double> z(zh.data(), order);
  // The budget per receiver picks the groups (receiver_budget.h); a kept group's caps
  // are all taken, so the size cull is off below.
  std::array<double, kMaxRankedGroups> bound_store{};
  std::array<bool, kMaxRankedGroups> dropped_store{};
  const bool ranked = candidates.size() <= static_cast<std::size_t>(kMaxRankedGroups);
  const std::span<double> bounds(bound_store.data(), ranked ? candidates.size() : 0);
  const std::span<bool> dropped(dropped_store.data(), bounds.size());
  for (std::size_t q = 0; q < bounds.size(); ++q)
    bounds[q] = node_cull_bound(groups.group(candidates[q]), r.position, r.normal, order);
  const double budget = listed_budget(options.blocker.cull_error, candidates.size(), groups.size());
  drop_smallest(bounds, budget, dropped);
  BlockerOptions every_cap = options.blocker;
  every_cap.cull_error = 0.0;
  int kept = 0;
  const auto below_plane = [&](const Sphere& extent) {
    return glm::dot(r.normal, extent.centre - r.position) + extent.radius <= 0.0;
  };
  const auto add = [&](const Sphere& s, const Sphere& extent) {
    if (below_plane(extent)) return;
    if (options.horizon_cull && horizon_side(extent, r) == HorizonSide::kBelow) return;
    kept += add_log_visibility(s, r.position, r.normal, every_cap, z, f_s) ? 1 : 0;
  };
  // Merging across the horizon keeps the hidden part of a node's cap, which costs at most
  // its cull bound: a node within the receiver's budget merges unchecked (no horizon
  // read; checking those too doubled ten airliners' cost on llvmpipe).
  const double unchecked = options.blocker.cull_error;
  const auto may_merge = [&](const SphereGroup& node, const Sphere& extent) {
    return !options.horizon_cull || node_cull_bound(node, r.position, r.normal, order) <= unchecked ||
           below_plane(extent) || horizon_side(extent, r) != HorizonSide::kAcross;
  };
  for (std::size_t q = 0; q < candidates.size(); ++q) {
    const std::uint32_t g = candidates[q];
    if (ranked ? dropped[q]
               : drop_unranked(node_cull_bound(groups.group(g), r.position, r.normal, order), budget, candidates.size()))
      continue;
    for_each_cap(spheres, groups, g, r.position, options.merge_sin, add, may_merge);
  }
  if (kept == 0) return 0;
  for (std::size_t q = 0; q < size; ++q) log_sum[q] = (r.log_t.empty() ? 0.0 : r.log_t[q]) + f_s[q];
  switch (options.composition) {
    case Composition::kLogSum:
      sh::exp_hyb<double>(log_sum, a, options.hyb);
      for (std::size_t q = 0; q < size; ++q) delta[q] = a[q] - r.vis_t[q];
      break;
    case Composition::kDelta:
      sh::exp_hyb<double>(log_sum, a, options.hyb);
      sh::exp_hyb<double>(r.log_t, b, options.hyb);
      for (std::size_t q = 0; q < size; ++q) delta[q] = a[q] - b[q];
      break;
    case Composition::kProduct:
      sh::exp_hyb<double>(f_s, a, options.hyb);
      sh::truncated_product<double>(r.vis_t, a, b);
      for (std::size_t q = 0; q < size; ++q) delta[q] = b[q] - r.vis_t[q];
      break;
  }
  return kept;
}

}  // namespace skylit::blockers
