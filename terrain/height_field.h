// The height field as data: float32 heights in metres on a regular grid, metric
// spacing, nodata mask and the georeferencing needed to write outputs.
//
// Grid convention (GDAL's): column i grows east, row j grows south; row 0 is the
// northern edge. Texel (i, j) has its centre at map position
// (i·dx, −j·dy) in a local metric frame with x east, y north.
//
// Staleness: every change to `heights` must go through mark_dirty() (the editing
// functions in terrain/editing.h do), which bumps `revision` and records the
// changed rectangle. Derived data (the pyramid) remembers the revision it was built
// from, so it can tell when it is stale instead of silently serving old heights.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "terrain/object_id.h"

namespace skylit::terrain {

struct GeoReference {
  std::array<double, 6> geotransform{0, 1, 0, 0, 0, -1};  // GDAL order
  std::string crs_wkt;                                     // empty: unknown CRS
  bool geographic = false;                                 // CRS in degrees
  bool has_geotransform = true;  // false: the source had none (outputs write none)
};

// Half-open pixel rectangle [x0, x0+width) × [y0, y0+height); empty when a side is ≤ 0.
struct PixelRect {
  int x0 = 0, y0 = 0, width = 0, height = 0;
  bool empty() const { return width <= 0 || height <= 0; }
  int x1() const { return x0 + width; }   // one past the last column
  int y1() const { return y0 + height; }  // one past the last row
  bool operator==(const PixelRect&) const = default;
};

// Smallest rectangle holding both (an empty one is ignored).
PixelRect bounding_union(const PixelRect& a, const PixelRect& b);

struct HeightField {
  int width = 0;
  int height = 0;
  std::vector<float> heights;        // row-major, width·height, metres; nodata filled
  std::vector<std::uint8_t> valid;   // 1 = measured height, 0 = nodata (filled for marching)
  double dy = 1.0;                   // north–south spacing (m), same for every row
  std::vector<double> dx_per_row;    // east–west spacing (m) of each row
  std::optional<double> nodata;      // nodata value to write in outputs, if any
  GeoReference georef;
  // Texel (0, 0)'s column and row in the raster this grid is a window of: the horizon
  // sweep lays its lines on that raster's lattice, so that overlapping windows agree.
  int origin_column = 0, origin_row = 0;

  // Change tracking: revision grows by one per mark_dirty(); last_dirty is the
  // rectangle of the most recent change (whole grid after construction/reads).
  std::uint64_t revision = 0;
  PixelRect last_dirty;
  // Which object this is (copies get a new id): GPU copies recognise their field by it.
  ObjectId id;

  HeightField() = default;
  HeightField(int w, int h, double spacing);  // flat, all valid, square spacing

  std::size_t size() const { return heights.size(); }
  float at(int i, int j) const { return heights[static_cast<std::size_t>(j) * width + i]; }
  float& at(int i, int j) { return heights[static_cast<std::size_t>(j) * width + i]; }
  bool is_valid(int i, int j) const { return valid[static_cast<std::size_t>(j) * width + i] != 0; }
  double dx(int j) const { return dx_per_row[j]; }
  double mean_dx() const;
  bool any_nodata() const;
  PixelRect bounds() const { return {0, 0, width, height}; }

  // Record that the heights inside `rect` (clipped to the grid) changed.
  void mark_dirty(const PixelRect& rect);
  void mark_all_dirty() { mark_dirty(bounds()); }
  // Whether exactly one change since `since_revision` (a copy kept of the field then)
  // touched only last_dirty, a rectangle inside the grid: what an incremental update of
  // that copy needs.
  bool one_edit_since(std::uint64_t since_revision) const;
};

}  // namespace skylit::terrain
