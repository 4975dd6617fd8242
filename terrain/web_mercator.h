// The web-map tile grid: WebMercatorQuad (EPSG:3857, spherical Mercator on the WGS 84
// semi-major axis), XYZ tile numbering (x grows east from −180°, y grows south from
// the top edge at +85.05°), 256- or 512-pixel tiles.
//
// Conventions (tests rely on them):
//  * Tile (z, x, y) covers the half-open 3857 box [xmin, xmax) × (ymin, ymax]: a point
//    exactly on a tile edge belongs to the tile east of it / south of it, as in
//    `tile_at`; "exactly" means within 1 µm, so boxes made from tile_bounds() select
//    their own tiles despite rounding. Pixel rows of a tile run north to south, as in GDAL rasters.
//  * Latitudes are clamped to ±kMaxLatitudeDeg (the square world's edge) before they
//    are projected; longitudes outside [−180°, 180°] are not wrapped.
//  * TMS (MBTiles rows) is the same grid with y counted from the south: tms_y().
#pragma once

#include <compare>
#include <numbers>
#include <string>

#include "terrain/geolocation.h"
#include "terrain/height_field.h"

namespace skylit::terrain {

inline constexpr double kWebMercatorRadius = 6378137.0;  // WGS 84 semi-major axis, metres
// Half the world's width in 3857 metres: π·R = 20037508.342789244.
inline constexpr double kWebMercatorOriginShift = std::numbers::pi * kWebMercatorRadius;
// atan(sinh(π)) in degrees: the latitude where the Mercator square ends.
inline constexpr double kWebMercatorMaxLatitudeDeg = 85.0511287798066;
inline constexpr int kMaxTileZoom = 30;  // 2^30 tiles per side still fits an int

// The one tile address of the project (tiles/ archives take it too). Ordered by z, then
// x, then y: archives list and merge tiles in that order.
struct TileId {
  int z = 0, x = 0, y = 0;  // XYZ
  bool operator==(const TileId&) const = default;
  auto operator<=>(const TileId&) const = default;
};

// Boxes: west ≤ east, south ≤ north.
struct MercatorBox {
  double xmin = 0, ymin = 0, xmax = 0, ymax = 0;  // EPSG:3857 metres
};
struct LonLatBox {
  double west = 0, south = 0, east = 0, north = 0;  // WGS 84 degrees
};
struct MercatorPoint {
  double x = 0, y = 0;
};

// Tiles [x0, x1] × [y0, y1] (inclusive) at zoom z; empty when x1 < x0 or y1 < y0.
struct TileRange {
  int z = 0;
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
  bool empty() const { return x1 < x0 || y1 < y0; }
  int columns() const { return empty() ? 0 : x1 - x0 + 1; }
  int rows() const { return empty() ? 0 : y1 - y0 + 1; }
  long long count() const { return static_cast<long long>(columns()) * rows(); }
  bool contains(const TileId& t) const { return t.z == z && t.x >= x0 && t.x <= x1 && t.y >= y0 && t.y <= y1; }
  bool operator==(const TileRange&) const = default;
};

struct ZoomRange {
  int min = 0, max = 0;  // inclusive
  bool operator==(const ZoomRange&) const = default;
};

// Tiles per side at zoom z (2^z). Every function taking a zoom throws
// std::invalid_argument outside [0, kMaxTileZoom], and for a tile size other than
// 256 or 512.
int tiles_per_side(int z);
int tms_y(int z, int y);  // 2^z − 1 − y (its own inverse)
// 0 ≤ z ≤ kMaxTileZoom and 0 ≤ x, y < 2^z; never throws (for input from files).
bool is_valid(const TileId& t);
std::string to_string(const TileId& t);  // "z/x/y", for messages

// 3857 metres per pixel at zoom z: 2πR / (tile_size · 2^z); 156543.03392804097 at z 0, 256 px.
double pixel_size(int z, int tile_size = 256);
// Ground metres per pixel at latitude φ: pixel_size · cos φ (Mercator's scale is 1/cos φ).
double ground_pixel_size(int z, double latitude_deg, int tile_size = 256);

double clamp_latitude(double latitude_deg);
// Spherical Mercator forward (latitude clamped first) and inverse.
MercatorPoint lon_lat_to_mercator(double lon_deg, double lat_deg);
LatLon mercator_to_lon_lat(double x, double y);

// The tile a column of the world's next copy (x ≥ 2^z) or previous one stands for.
TileId wrap_tile(const TileId& t);

MercatorBox tile_bounds(const TileId& t);
LonLatBox tile_lon_lat_bounds(const TileId& t);

// The tile holding a point (edge points go east/south; the world's east and south
// edges map to the last tile). Points outside the world are clamped onto it.
TileId tile_at(double lon_deg, double lat_deg, int z);

// Tiles overlapping a box with positive area (touching an edge does not count; a
// zero-width box still selects the tile it lies in), clipped to the world. A box that
// starts inside the world and runs past its east edge (a DEM across the antimeridian,
// dem_mercator_bounds) goes on into the world's next copy: columns x ≥ 2^z, at most 2^z
// of them in all, which wrap_tile folds back.
TileRange tiles_covering(const MercatorBox& box, int z);
TileRange tiles_covering(const LonLatBox& box, int z);  // latitudes clamped

// The DEM's extent on the tile grid: its pixel edges (kGridEdgeSamples points per
// edge, so a projected DEM's curved 3857 outline is bounded within metres) through its
// CRS to WGS 84, as a WGS 84 and a 3857 box. West lies in −180…180°; for a DEM across
// the antimeridian east runs on past 180° (east − 360° in −180…180°), and the 3857
// box past the world's east edge. Throws DemError when the DEM has no CRS or
// geotransform.
inline constexpr int kGridEdgeSamples = 64;
LonLatBox dem_lon_lat_bounds(const HeightField& dem);
MercatorBox dem_mercator_bounds(const HeightField& dem);

// Native zoom of a DEM: the smallest zoom whose ground pixel size at the DEM's centre
// latitude is at or finer than the DEM's ground resolution,
//   min { z : pixel_size(z) · cos φ_centre ≤ min(dem.dy, dem.dx(centre row)) }.
// The DEM's ground resolution is its finer axis in the reader's metric spacing (a
// projected CRS' metres, ellipsoidal arcs for degrees), so no zoom below native loses
// less detail than needed and native is the first that keeps all of it. (gdal2tiles
// picks the last zoom at or coarser than the DEM's 3857 pixel size: usually one less.)
// Throws DemError when the DEM has no CRS or geotransform; capped at kMaxTileZoom.
int native_zoom(const HeightField& dem, int tile_size = 256);
// Default zoom range: [native − 5, native], the lower end clamped to 0.
ZoomRange default_zoom_range(int native);

}  // namespace skylit::terrain
