// The fingerprint of a `skylit tiles` run (tiles/fingerprint.h): everything its tile
// bytes depend on, as "key=value" lines. Not in it: the output path, --name and -w (they
// change the metadata or files beside the tiles, not the tiles), --shard (shards of one
// run must merge and resume into each other), --threads and -q.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/tiles/tile_plan.h"
#include "shading/lighting.h"
#include "terrain/web_mercator.h"
#include "tiles/metadata.h"

namespace skylit::app::tiles {

struct RunOptions {
  std::vector<std::string> inputs;  // DEM files
  std::string product, quality, resampling, tone;  // resampling "": the per-zoom default
  shading::LightingRequest light;
  terrain::ZoomRange zooms;
  int tile_size = 256;
  skylit::tiles::TileFormat format = skylit::tiles::TileFormat::Png;
  bool tms = false;
  std::vector<ZoomPlan> plans;  // each zoom's halo and horizon distance
  std::optional<terrain::LonLatBox> bounds;  // --bounds (parsed); recorded only when given
};

// Each DEM enters as its absolute path, size and modification time (reading every byte
// would cost more than a small run); the version is skylit's, whose code makes the bytes.
std::string run_fingerprint(const RunOptions& o);

}  // namespace skylit::app::tiles
