// What a `skylit tiles` run renders, decided before any rendering: per zoom the halo and
// the horizon distance it makes exact, a fixed grid of window blocks, and a shard's share
// of the blocks. Everything here is a pure function of the DEM's bounds and the options,
// so every run (and every shard) cuts each tile from the same window: tiles are
// byte-identical whichever run or shard renders them.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "shading/horizon/halo.h"
#include "terrain/web_mercator.h"

namespace skylit::app::tiles {

// Default horizon search distance (ground metres), and the pixels past it that the
// march's kernels read (shading/horizon/halo.h).
inline constexpr double kDefaultMaxDistanceM = horizon::kDefaultBoundedDistanceM;
inline constexpr int kKernelMargin = horizon::kKernelMarginTexels;
// The default halo is clamped to this pixel range: at least a few pixels at low zooms
// (normals and pyramid kernels read past the tile), at most this many at high zooms
// (where the distance then shrinks to what the halo holds).
inline constexpr int kMinHalo = 16;
inline constexpr int kMaxHalo = 256;
// Largest halo an explicit --halo or --max-distance may ask for.
inline constexpr int kMaxUserHalo = 4096;
// Window blocks: at most kBlockPixels pixels of tiles per side; fewer rows where the
// window's single north–south spacing would stray more than kMaxDyError from its rows'
// (TileWindow::max_dy_error).
inline constexpr int kBlockPixels = 2048;
inline constexpr double kMaxDyError = 0.005;

struct ZoomPlan {
  int z = 0;
  int halo = 0;                  // pixels on every side of a window
  double max_distance_m = 0.0;   // passed to the horizon search: what the halo holds
  int block_columns = 1, block_rows = 1;  // tiles per window block
  terrain::TileRange covering;   // tiles over the DEM's bounds
};

struct HaloRequest {
  std::optional<int> halo;             // --halo
  std::optional<double> max_distance;  // --max-distance (metres, > 0)
};

// The halo/distance rule (docs/tiles.md): g = the zoom's ground pixel at the DEM's
// poleward edge (its smallest); by default H = clamp(⌈D/g⌉ + margin, kMinHalo, kMaxHalo)
// with D = kDefaultMaxDistanceM, and the distance passed on is (H − margin)·g capped at D,
// so no ray of a tile pixel leaves its window. --max-distance D sets D (H unclamped),
// --halo H sets H (and D = (H − margin)·g unless given too). Throws std::invalid_argument
// for a halo over kMaxUserHalo or under the margin.
ZoomPlan plan_zoom(const terrain::MercatorBox& dem_bounds, double poleward_latitude_deg, int z, int tile_size,
                   const HaloRequest& request);

struct Block {
  int z = 0;
  int column = 0, row = 0;       // block index from the covering range's corner
  terrain::TileRange tiles;      // the block's tiles that cover the DEM: its window
  terrain::TileRange wanted;     // those the run writes (all of them but with --bounds)
  double cost = 0.0;             // pixels to render, halo included
  bool operator==(const Block&) const = default;
};

// The zoom's blocks: the covering range cut into the fewest blocks of at most
// block_columns × block_rows tiles, ⌈columns/block_columns⌉ × ⌈rows/block_rows⌉ of
// near-equal sides (the first ones a tile longer), in row-major order; Block::column and
// row count blocks from the range's corner.
std::vector<Block> blocks(const ZoomPlan& plan, int tile_size);

// --bounds W,S,E,N in WGS 84 degrees; W > E runs across the antimeridian (E then comes
// back past 180°, as dem_lon_lat_bounds gives east). Throws std::invalid_argument naming
// --bounds for text that is not four numbers, or a box outside the globe or without area.
terrain::LonLatBox parse_bounds(const std::string& text);

// The part of the DEM's box (dem_lon_lat_bounds) inside `bounds`, in the DEM box's
// longitudes; nullopt where they do not overlap (touching edges do not).
std::optional<terrain::LonLatBox> bounded_box(const terrain::LonLatBox& dem, const terrain::LonLatBox& bounds);

// The blocks narrowed to the tiles over `box` (tiles_covering at each block's zoom),
// dropping those left with none. A kept block keeps its window (Block::tiles), so its
// tiles are those of the run without bounds, byte for byte.
std::vector<Block> within(const std::vector<Block>& blocks, const terrain::LonLatBox& box);

struct Shard {
  int index = 1, count = 1;  // 1 ≤ index ≤ count
};
// Parses "i/N" (1-based, 1 ≤ i ≤ N); throws std::invalid_argument naming --shard.
Shard parse_shard(const std::string& text);

// Shard i's blocks: the blocks sorted by cost (largest first, ties by zoom, row, column)
// go one by one to the shard with the least cost so far (ties: the lowest index), so the
// shards' costs differ by at most one block's. Returned in the input order.
std::vector<Block> shard_blocks(const std::vector<Block>& all, const Shard& shard);

}  // namespace skylit::app::tiles
