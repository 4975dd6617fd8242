// The rendering loop of `skylit tiles`: each block's window warped from the DEM, shaded
// by the renderer (or encoded as DEM RGB), cut into tiles that go to the archive.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "app/tiles/tile_plan.h"
#include "shading/renderer.h"
#include "terrain/dem_tile_encoding.h"
#include "terrain/tile_window.h"
#include "app/tiles/lazy_archive.h"

namespace skylit::app::tiles {

struct TileJob {
  int tile_size = 256;
  std::optional<terrain::Resampling> resampling;  // empty: the window's per-zoom default
  // Either a shading product (with its options and lighting) or a DEM encoding.
  std::optional<shading::Product> product;
  shading::ProductOptions options;  // max_distance_m is set per zoom from its plan
  std::optional<terrain::DemEncoding> encoding;
  skylit::tiles::TileFormat format = skylit::tiles::TileFormat::Png;
  unsigned threads = 0;  // tile encoding threads (0: all cores); the renderer's are options.threads
  bool quiet = false;
};

struct RunCounts {
  long long written = 0, skipped = 0, empty = 0;  // empty: wholly outside the DEM
};

// Renders `blocks` (of `plans`, one per zoom) into `archive`, skipping tiles it already
// has. `renderer` is needed for products only.
RunCounts render_blocks(const terrain::TileWindowSource& source, const std::vector<ZoomPlan>& plans,
                        const std::vector<Block>& blocks, const TileJob& job, shading::Renderer* renderer,
                        LazyArchive& archive);

}  // namespace skylit::app::tiles
