// Per-zoom height windows for web-map tiles: the DEM's staged copy (staged_dem.h)
// warped by GDAL's warper onto zoom z's EPSG:3857 pixel grid over a rectangle of tiles
// plus a halo of H pixels on every side, as a HeightField the renderer shades directly.
//
// Policy decisions (tests rely on them):
//  * Grid: pixel (i, j) of a window over tiles [x0..x1] × [y0..y1] is global pixel
//    (x0·T − H + i, y0·T − H + j) of the zoom, T the tile size; the same global pixel
//    gets the same height, bit for bit, in every window that holds it, so tiles are
//    seamless. For that the transformer maps global pixels to the DEM the same way in
//    every window (terrain/zoom_transform.h: PROJ at the nodes of a grid fixed in the
//    zoom's pixels, bilinear in between, within kNodeTolerancePx = 0.001 source pixels
//    of the exact transform; where gdalwarp -et 0 runs PROJ per pixel, half a hillshade
//    tile run's time) and the kernel's scale is fixed per zoom (warp options
//    XSCALE/YSCALE, from the DEM's centre, with SOURCE_EXTRA padding) instead of GDAL's
//    per-chunk estimate, which differs between windows when downsampling with a kernel
//    (0.3–0.7 m seams at z 11 on Big Tujunga without it).
//  * Resampling: default_resampling(z, native) = cubic at and above the native zoom
//    (upsampling: cubic interpolates the DEM's samples with continuous slopes, where
//    bilinear shades as flat facets with a visible DEM grid and cubicspline smooths
//    peaks away), average below it (downsampling: the area mean of the DEM pixels
//    under each output pixel keeps mean heights and cannot overshoot at cliffs and
//    coasts, where cubic rings; it is the usual DEM-pyramid choice, gdaladdo -r
//    average). It depends only on the zoom, never on how tiles are grouped in windows.
//  * Outside the DEM and at its voids: valid = 0, heights filled by options.fill (as
//    the reader fills voids) so marching sees a continuous surface; the caller makes
//    those pixels transparent. A window that misses the DEM is not an error: it comes
//    back with valid_count == 0 (empty()), all heights 0.
//  * Spacing: 3857 metres are not ground metres. On the sphere of radius R a pixel of
//    p Mercator metres at latitude φ spans p·cos φ ground metres both ways, so row j
//    (centre latitude φ_j) has dx_per_row[j] = dy_per_row[j] = p·cos φ_j: pixels are
//    square on the ground but shrink northward. HeightField has one dy for all rows
//    (the renderer places row j at −j·dy), so field.dy is the window's north–south
//    ground extent R·(φ_top − φ_bottom) divided by its rows, the rule the reader uses
//    for geographic grids; dy_per_row keeps the exact values and max_dy_error() says
//    how far they stray from field.dy (≈ sin φ · rows · π / (T·2^z), e.g. 0.3 % for
//    384 rows at z 10 and 45°; keep windows short at low zooms).
//  * Errors (one line each): a DEM without a CRS or geotransform, or a GDAL failure:
//    DemError; a bad zoom, tile size, tile range or halo, or a window over 2^28
//    pixels: std::invalid_argument.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "terrain/dem_reader.h"
#include "terrain/height_field.h"
#include "terrain/staged_dem.h"
#include "terrain/web_mercator.h"

namespace skylit::terrain {

enum class Resampling { Nearest, Bilinear, Cubic, CubicSpline, Lanczos, Average };

// GDAL's names (gdalwarp -r): near, bilinear, cubic, cubicspline, lanczos, average.
std::string_view resampling_name(Resampling r);
std::optional<Resampling> parse_resampling(std::string_view name);
// Cubic for z ≥ native (upsampling), average below (downsampling); see above.
Resampling default_resampling(int zoom, int native);

struct TileWindowOptions {
  int tile_size = 256;                    // 256 or 512
  int halo = 0;                           // pixels added on every side (≥ 0)
  std::optional<Resampling> resampling{}; // empty: default_resampling(z, native zoom)
  VoidFill fill = VoidFill::Laplace;      // how outside/void pixels are filled
};

struct TileWindow {
  HeightField field;               // EPSG:3857 georef; valid = 0 outside the DEM and at voids
  TileRange tiles;
  int tile_size = 256;
  int halo = 0;
  Resampling resampling = Resampling::Cubic;
  std::vector<double> dy_per_row;  // exact ground north–south spacing per row (= dx_per_row)
  std::size_t valid_count = 0;     // pixels with valid == 1

  bool empty() const { return valid_count == 0; }
  // Where tile t's T × T pixels lie in `field` (throws std::out_of_range if t is not in tiles).
  PixelRect tile_rect(const TileId& t) const;
  // max_j |dy_per_row[j] / field.dy − 1|: the relative north–south spacing error the
  // renderer's single dy makes at the window's top or bottom row.
  double max_dy_error() const;
};

// The warper's settings for one zoom. arguments() are the equivalent gdalwarp options
// with the exact transformer (-et 0), after the window's -te/-ts: the reference the
// tests compare with; window() runs GDAL's warper with the same options and the node
// grid of node_spacing global pixels instead of -et 0.
struct WarpSettings {
  Resampling resampling = Resampling::Cubic;
  double xscale = 1.0, yscale = 1.0;  // destination pixels per source pixel, ≤ 1
  int source_extra = 0;               // source pixels read beyond the kernel's estimate
  int node_spacing = 1;               // global pixels between exact transforms (zoom_transform.h)
  double node_error_bound_px = 0.0;   // its bilinear error bound, source pixels
  std::vector<std::string> arguments() const;  // -t_srs EPSG:3857 -r … -et 0 -wo …
};

// Throws DemError (one line) unless a DEM with this georeference can be warped to
// EPSG:3857: it needs a CRS and a geotransform.
void check_warpable(const GeoReference& georef);

// The DEM prepared once for many windows (terrain/staged_dem.h: a Float32 copy with
// NaN at voids, in memory or on disk). Not thread-safe: use one source per thread.
class TileWindowSource {
 public:
  // Throws DemError when the DEM has no CRS or no geotransform, or its CRS is unusable.
  explicit TileWindowSource(StagedDem dem);
  explicit TileWindowSource(const HeightField& dem);  // staged in memory
  ~TileWindowSource();
  TileWindowSource(TileWindowSource&&) noexcept;
  TileWindowSource& operator=(TileWindowSource&&) noexcept;

  const StagedDem& dem() const;
  int native_zoom(int tile_size = 256) const;
  WarpSettings warp_settings(int zoom, const TileWindowOptions& options = {}) const;
  TileWindow window(const TileRange& tiles, const TileWindowOptions& options = {}) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace skylit::terrain
