// Spheres binned into square tiles of receivers (DESIGN.md "Aircraft"): each tile lists
// the sphere groups (sphere_groups.h) that can darken its sky above the error target and
// the spheres that can block its sun, so a texel tests only those and the cost of an
// aircraft follows the ground it darkens.
// Bins are conservative: a listed sphere may still be culled per texel.
#pragma once

#include "shading/blockers/sphere_blocker.h"
#include "shading/blockers/sphere_groups.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace skylit::blockers {

// The receivers: texel (i, j) is at (i·dx_j, −j·dy) with a height in [z_min, z_max],
// dx_j in [dx_min, dx] (the rows' east–west spacings: one value on projected grids).
struct ReceiverGrid {
  int width = 0, height = 0;
  double dx = 1.0, dy = 1.0;
  double z_min = 0.0, z_max = 0.0;
  double dx_min = 0.0;  // 0: dx
};

inline constexpr int kBinTexels = 16;  // tile edge, texels

class SphereBins {
 public:
  // Sky bins of the groups a receiver's budget (options.cull_error) may keep at SH order
  // `order` (receiver_budget.h: none whose bound is under budget/N of N groups); sun bins of the
  // spheres when `sun` (unit, toward the sun) is above the horizontal, for a disc of
  // `disc_radius`.
  SphereBins(std::span<const Sphere> spheres, const SphereGroups& groups, const ReceiverGrid& grid, int order,
             const BlockerOptions& options, std::optional<glm::dvec3> sun, double disc_radius);

  int tiles_x() const { return tiles_x_; }
  int tiles_y() const { return tiles_y_; }
  // Indices into the groups (sky) and the spheres (sun) of the tile holding texel (i, j).
  std::span<const std::uint32_t> sky(int i, int j) const { return list(sky_, i, j); }
  std::span<const std::uint32_t> sun(int i, int j) const { return list(sun_, i, j); }
  // Tiles listing at least one sphere (for reports and the GPU's tile dispatch).
  int sky_tiles() const { return busy(sky_); }
  int sun_tiles() const { return busy(sun_); }
  // Flat form (the GPU's): offsets[t] … offsets[t + 1] index into indices, t = ty·tiles_x + tx.
  struct Flat {
    std::vector<std::uint32_t> offsets, indices;
  };
  Flat flat_sky() const { return flatten(sky_); }
  Flat flat_sun() const { return flatten(sun_); }

 private:
  using Lists = std::vector<std::vector<std::uint32_t>>;
  std::span<const std::uint32_t> list(const Lists& l, int i, int j) const {
    return l[static_cast<std::size_t>(j / kBinTexels) * tiles_x_ + i / kBinTexels];
  }
  static int busy(const Lists& l);
  static Flat flatten(const Lists& l);
  // Adds sphere s to every tile meeting the box [x0, x1] × [y0, y1] (field metres) and,
  // with rho, the disc of that radius about (cx, cy).
  void add(Lists& l, std::uint32_t s, double x0, double x1, double y0, double y1, double cx = 0.0, double cy = 0.0,
           double rho = -1.0);

  ReceiverGrid grid_;
  int tiles_x_ = 0, tiles_y_ = 0;
  Lists sky_, sun_;
};

}  // namespace skylit::blockers
