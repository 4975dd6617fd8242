#include "shading/blockers/sphere_bins.h"

#include "shading/blockers/receiver_budget.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace skylit::blockers {

SphereBins::SphereBins(std::span<const Sphere> spheres, const SphereGroups& groups, const ReceiverGrid& grid, int order,
                       const BlockerOptions& options, std::optional<glm::dvec3> sun, double disc_radius)
    : grid_(grid),
      tiles_x_((grid.width + kBinTexels - 1) / kBinTexels),
      tiles_y_((grid.height + kBinTexels - 1) / kBinTexels),
      sky_(static_cast<std::size_t>(tiles_x_) * tiles_y_),
      sun_(sky_.size()) {
  const double inf = std::numeric_limits<double>::infinity();
  for (std::uint32_t k = 0; k < groups.size(); ++k) {
    // Sky: receivers within the group's reach at budget/N (N groups: a receiver keeps
    // none whose bound is under that, receiver_budget.h); the nearest lie at height z_max.
    const SphereGroup& g = groups.group(k);
    const double reach = node_reach(g, order, unlisted_share(options.cull_error, groups.size()));
    const double above = std::max(0.0, g.centre.z - grid.z_max);
    if (reach == inf) {
      add(sky_, k, -inf, inf, -inf, inf);
    } else if (above < reach) {
      const double rho = std::sqrt(reach * reach - above * above);
      add(sky_, k, g.centre.x - rho, g.centre.x + rho, g.centre.y - rho, g.centre.y + rho, g.centre.x, g.centre.y, rho);
    }
  }
  for (std::uint32_t k = 0; k < spheres.size(); ++k) {
    const Sphere& s = spheres[k];
    // Sun: receivers at heights [z_min − r, z_max + r] whose ray toward the sun can pass
    // within r of the centre (plus the penumbra's spread over the distance).
    if (!sun || !(sun->z > 0.0)) continue;
    const glm::dvec3 d = *sun;
    const double t_near = std::max(0.0, (s.centre.z - grid.z_max - s.radius) / d.z);
    const double t_far = (s.centre.z - grid.z_min + s.radius) / d.z;
    if (t_far <= 0.0) continue;  // below every receiver
    const double spread = (s.radius + t_far * std::tan(disc_radius)) / d.z;
    const double xa = s.centre.x - d.x * t_near, xb = s.centre.x - d.x * t_far;
    const double ya = s.centre.y - d.y * t_near, yb = s.centre.y - d.y * t_far;
    add(sun_, k, std::min(xa, xb) - spread, std::max(xa, xb) + spread, std::min(ya, yb) - spread,
        std::max(ya, yb) + spread);
  }
}

void SphereBins::add(Lists& l, std::uint32_t s, double x0, double x1, double y0, double y1, double cx, double cy,
                     double rho) {
  // Texel i of row j covers x ∈ [(i − ½)dx_j, (i + ½)dx_j], dx_j ∈ [dx_min, dx]; row j
  // covers y ∈ [−(j + ½)dy, −(j − ½)dy].
  auto clamp_index = [](double v, int n) {
    if (!(v > 0.0)) return 0;  // also −∞ and NaN
    return v >= n - 1 ? n - 1 : static_cast<int>(v);
  };
  const double dx_hi = grid_.dx, dx_lo = grid_.dx_min > 0.0 ? grid_.dx_min : grid_.dx;
  if (x1 < -0.5 * dx_hi || x0 > (grid_.width - 0.5) * dx_hi) return;
  if (-y0 < -0.5 * grid_.dy || -y1 > (grid_.height - 0.5) * grid_.dy) return;
  // Texels whose x may lie in [x0, x1] on some row (x ≥ 0: the widest rows first).
  const int i0 = clamp_index(x0 / dx_hi + 0.5, grid_.width), i1 = clamp_index(x1 / dx_lo + 0.5, grid_.width);
  const int j0 = clamp_index(-y1 / grid_.dy + 0.5, grid_.height), j1 = clamp_index(-y0 / grid_.dy + 0.5, grid_.height);
  for (int ty = j0 / kBinTexels; ty <= j1 / kBinTexels; ++ty)
    for (int tx = i0 / kBinTexels; tx <= i1 / kBinTexels; ++tx) {
      if (rho >= 0.0) {  // the tile's extent against the disc: its nearest point
        const double tx0 = (tx * kBinTexels - 0.5) * dx_lo, tx1 = ((tx + 1) * kBinTexels - 0.5) * dx_hi;
        const double ty1 = -(ty * kBinTexels - 0.5) * grid_.dy, ty0 = -((ty + 1) * kBinTexels - 0.5) * grid_.dy;
        const double ex = std::max({tx0 - cx, 0.0, cx - tx1}), ey = std::max({ty0 - cy, 0.0, cy - ty1});
        if (ex * ex + ey * ey > rho * rho) continue;
      }
      l[static_cast<std::size_t>(ty) * tiles_x_ + tx].push_back(s);
    }
}

int SphereBins::busy(const Lists& l) {
  return static_cast<int>(std::count_if(l.begin(), l.end(), [](const auto& v) { return !v.empty(); }));
}

SphereBins::Flat SphereBins::flatten(const Lists& l) {
  Flat f;
  f.offsets.reserve(l.size() + 1);
  f.offsets.push_back(0);
  for (const auto& v : l) {
    f.indices.insert(f.indices.end(), v.begin(), v.end());
    f.offsets.push_back(static_cast<std::uint32_t>(f.indices.size()));
  }
  return f;
}

}  // namespace skylit::blockers
