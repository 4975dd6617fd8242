// `shade` of a DEM larger than one frame (issue 15, DESIGN.md "Scale"): the DEM is read
// in windows, each a block's core grown by a halo the horizon search distance wide, shaded
// by the renderer, and its core written into the output block by block, so memory is
// bounded by the block, not the DEM. Blocks are sized by the GPU's limits (gpu/field_limits.h)
// and a memory budget; a blocked run bounds the search distance (5 km by default).
#pragma once

#include "app/shade/shade_output.h"
#include "app/shade/tinted_relief.h"
#include "shading/renderer.h"
#include "terrain/block_grid.h"
#include "terrain/dem_reader.h"

#include <optional>
#include <string>
#include <vector>

namespace skylit::app::shade {

// Side (texels, halo included) of the largest block when no GPU limit is lower: about
// 1.8 GB of host memory on llvmpipe, 0.8 GB on the CPU reference (docs/large-dems.md).
inline constexpr int kBlockBudgetSide = 3072;
// DEMs with more texels than this are shaded in blocks by default (4096²).
inline constexpr long long kMaxWholeFieldTexels = 4096LL * 4096LL;
// The smallest core --block-size takes.
inline constexpr int kMinBlockCore = 16;

struct BlockPlan {
  int core = 0;                 // block side written (texels)
  int halo = 0;                 // texels read on every side
  double max_distance_m = 0.0;  // the horizon search distance the halo holds (0: local product)
  std::vector<terrain::RasterBlock> blocks;
  std::vector<std::string> notes;  // one line each: why blocks, the distance chosen
};

// The blocks of `product` over this DEM, or nothing where the whole DEM is one frame:
// `requested` is --block-size (nothing: auto, blocks only where the DEM exceeds the GPU's
// limit or kMaxWholeFieldTexels). `options.march.max_distance_m` 0 picks the bounded
// default. Throws std::invalid_argument (one line) for a block that cannot hold its halo.
std::optional<BlockPlan> plan_blocks(const terrain::DemInfo& dem, double smallest_spacing_m,
                                     shading::Product product, const shading::ProductOptions& options,
                                     std::optional<int> requested, shading::Renderer& renderer);

struct BlockedShade {
  std::vector<std::string> inputs;
  terrain::DemReadOptions read;              // band, scales, z, nodata (no window)
  shading::Product product = shading::Product::Shaded;
  shading::ProductOptions options;           // max_distance_m from the plan
  std::optional<shading::Lighting> lighting;
  std::vector<blockers::Sphere> crs_spheres;  // --spheres, in the DEM's CRS
  std::optional<TintArgs> tint;
  OutputSpec out;
  bool quiet = false;
};

// Shades every block and writes the output (atomically: nothing is left on failure).
void run_blocked_shade(const BlockedShade& job, const BlockPlan& plan, const terrain::DemInfo& dem,
                       shading::Renderer& renderer);

}  // namespace skylit::app::shade
