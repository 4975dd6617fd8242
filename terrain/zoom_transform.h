// Where a zoom's EPSG:3857 pixels fall in the DEM: the exact transform (PROJ through
// OGR, as gdalwarp -et 0 computes it) and the approximation the tile windows warp with.
//
// Policy decisions (tests rely on them):
//  * Coordinates: "global pixels" of zoom z are the zoom's whole pixel grid, global
//    pixel (gx, gy) covering x = −S + gx·p … −S + (gx+1)·p, y = S − gy·p … (S the
//    half width, p = pixel_size(z)); centres at gx + 0.5. "Source pixels" are the DEM's
//    pixel/line coordinates (0, 0 its top-left corner), GDAL's warper convention.
//  * Approximation: the exact transform at the nodes (i·N, j·N) of a grid FIXED in
//    global pixels, bilinear in between. The nodes depend only on the zoom and N, not
//    on which window asks, so every window computes the same source point, bit for
//    bit, for a global pixel: tiles stay seamless and byte-identical across reruns,
//    shards and window layouts.
//  * Spacing N per zoom: the largest power of two ≤ kMaxNodeSpacing whose bilinear
//    error bound N²/8 · (M_xx + M_yy) is ≤ kNodeTolerancePx, M the largest second
//    derivative of the source coordinates in global pixels (sampled over the DEM's
//    Mercator box widened by its size on every side, which holds every window's halo:
//    see curvature()). N = 1 means no approximation: every point exact (where even
//    one-pixel cells would miss the tolerance: the low zooms of fine DEMs).
//  * A node PROJ cannot transform makes the pixels of its four cells fail (outside).
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "terrain/height_field.h"
#include "terrain/web_mercator.h"

class OGRCoordinateTransformation;

namespace skylit::terrain {

// The bound the node spacing keeps, in source pixels: ten times under the 0.01 px the
// tile windows promise (a 1/100 pixel shift moves a cubic height by ≤ 2 % of one DEM
// step), so the sampled curvature may be off by a factor of ten before that breaks.
inline constexpr double kNodeTolerancePx = 1e-3;
// Beyond 32 the node transforms cost nothing measurable (1/1024 of the pixels), so a
// longer spacing would only widen the error where the curvature estimate is short.
inline constexpr int kMaxNodeSpacing = 32;

// Largest |∂²s/∂x²| and |∂²s/∂y²| over both source coordinates s, in source pixels per
// Mercator metre²; a zoom's value in global pixels is this × p².
struct Curvature {
  double xx = 0.0, yy = 0.0;
};

// The exact transform of one DEM: Mercator metres ↔ source pixels. Not thread-safe
// (PROJ contexts): one per thread, like TileWindowSource.
class MercatorToDem {
 public:
  // Throws DemError if the DEM's CRS is missing or PROJ has no path from EPSG:3857.
  // Longitudes wrap toward the DEM: a point reaches a DEM in degrees at the longitude
  // the DEM stores (e.g. 180.5° E, not −179.5°), and 3857 results lie within half a
  // world of the DEM's centre (dem_mercator_bounds: past the east edge for a DEM across
  // the antimeridian).
  explicit MercatorToDem(const HeightField& dem);
  ~MercatorToDem();
  MercatorToDem(MercatorToDem&&) noexcept;
  MercatorToDem& operator=(MercatorToDem&&) noexcept;

  // In place, n points: Mercator metres → source pixels (forward) or back (inverse);
  // ok[k] = 0 where PROJ fails (x, y then unspecified).
  void to_source(std::size_t n, double* x, double* y, int* ok) const;
  void to_mercator(std::size_t n, double* x, double* y, int* ok) const;
  // Second differences over a 9 × 9 sample of `box` at a step of 1/16 of its sides.
  Curvature curvature(const MercatorBox& box) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// kNodeTolerancePx's rule above for one zoom (p: its Mercator pixel size).
int node_spacing(const Curvature& c, double p);
// The rule's bound N²/8 · (M_xx + M_yy) in source pixels (0 for N = 1: exact).
double node_error_bound(const Curvature& c, double p, int spacing);

// The approximation over one window: nodes cached for the global pixel rectangle
// [gx0, gx1] × [gy0, gy1]; points outside it still get the window-independent
// answer, from nodes transformed on demand.
class NodeGrid {
 public:
  NodeGrid(const MercatorToDem& exact, int zoom, int tile_size, int spacing, long long gx0, long long gy0, long long gx1,
           long long gy1);
  int spacing() const { return spacing_; }
  // Global pixel coordinates → source pixels; false where a node failed.
  bool source(double gx, double gy, double& sx, double& sy) const;
  // source() of n points (offset_x + x[k], offset_y + y[k]) in place, ok[k] its result:
  // the same bits, with each cell's nodes fetched once per run of points in it.
  void sources(std::size_t n, double* x, double* y, int* ok, double offset_x, double offset_y) const;
  // The exact transform of the same point (for tests and the inverse direction).
  bool exact_source(double gx, double gy, double& sx, double& sy) const;
  // Source pixels → global pixel coordinates, exact.
  bool global_pixel(double sx, double sy, double& gx, double& gy) const;

 private:
  struct Node {
    double x = 0, y = 0;
    bool ok = false;
  };
  struct Cell {
    long long i = 0, j = 0;
    Node a, b, c, d;  // nodes (i, j), (i+1, j), (i, j+1), (i+1, j+1)
    bool ok = false;
  };
  Node node(long long i, long long j) const;
  Cell cell(long long i, long long j) const;
  void locate(double gx, double gy, long long& i, long long& j, double& fx, double& fy) const;
  static void interpolate(const Cell& c, double fx, double fy, double& sx, double& sy);

  const MercatorToDem* exact_;
  double p_;
  int spacing_;
  long long i0_ = 0, j0_ = 0, ni_ = 0, nj_ = 0;  // cached node indices [i0, i0+ni) × [j0, j0+nj)
  std::vector<Node> nodes_;
};

// A GDALTransformerFunc over a NodeGrid for one window whose pixel (0, 0) is global
// pixel (gx0, gy0): the warper passes window pixel coordinates.
struct WindowTransformArg {
  const NodeGrid* grid = nullptr;
  long long gx0 = 0, gy0 = 0;
};
int window_transform(void* arg, int dst_to_src, int n, double* x, double* y, double* z, int* ok);

}  // namespace skylit::terrain
