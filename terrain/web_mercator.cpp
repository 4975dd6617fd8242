// WebMercatorQuad tile arithmetic (spherical Mercator, XYZ numbering) and the native
// zoom of a DEM.
#include "terrain/web_mercator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "terrain/dem_reader.h"

namespace skylit::terrain {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

void check_zoom(int z) {
  if (z < 0 || z > kMaxTileZoom)
    throw std::invalid_argument("zoom " + std::to_string(z) + " is outside 0…" + std::to_string(kMaxTileZoom));
}

void check_tile_size(int tile_size) {
  if (tile_size != 256 && tile_size != 512)
    throw std::invalid_argument("tile size " + std::to_string(tile_size) + " is not 256 or 512");
}

void check_tile(const TileId& t) {
  if (!is_valid(t))
    throw std::invalid_argument("tile " + to_string(t) + " does not exist (x and y run 0…" +
                                std::to_string(tiles_per_side(t.z) - 1) + ")");
}

// Width of one tile in 3857 metres.
double tile_span(int z) { return 2.0 * kWebMercatorOriginShift / tiles_per_side(z); }

int clamp_index(double v, int n) { return static_cast<int>(std::clamp(v, 0.0, static_cast<double>(n - 1))); }

// Position in tiles of a distance from the world's west (or north) edge; within
// kEdgeSnapMetres of a tile edge it is that edge exactly, so boxes built from
// tile_bounds() (a few ulps off) select their own tiles and no neighbour.
constexpr double kEdgeSnapMetres = 1e-6;
double in_tiles(double metres, double span) {
  const double f = metres / span, r = std::round(f);
  return std::abs(f - r) * span < kEdgeSnapMetres ? r : f;
}

}  // namespace

int tiles_per_side(int z) {
  check_zoom(z);
  return 1 << z;
}

int tms_y(int z, int y) { return tiles_per_side(z) - 1 - y; }

bool is_valid(const TileId& t) {
  if (t.z < 0 || t.z > kMaxTileZoom) return false;
  const int n = 1 << t.z;
  return t.x >= 0 && t.x < n && t.y >= 0 && t.y < n;
}

std::string to_string(const TileId& t) {
  return std::to_string(t.z) + "/" + std::to_string(t.x) + "/" + std::to_string(t.y);
}

double pixel_size(int z, int tile_size) {
  check_tile_size(tile_size);
  return tile_span(z) / tile_size;
}

double ground_pixel_size(int z, double latitude_deg, int tile_size) {
  return pixel_size(z, tile_size) * std::cos(clamp_latitude(latitude_deg) * kDegToRad);
}

double clamp_latitude(double latitude_deg) {
  return std::clamp(latitude_deg, -kWebMercatorMaxLatitudeDeg, kWebMercatorMaxLatitudeDeg);
}

MercatorPoint lon_lat_to_mercator(double lon_deg, double lat_deg) {
  const double phi = clamp_latitude(lat_deg) * kDegToRad;
  return {kWebMercatorRadius * lon_deg * kDegToRad, kWebMercatorRadius * std::asinh(std::tan(phi))};
}

LatLon mercator_to_lon_lat(double x, double y) {
  return {std::atan(std::sinh(y / kWebMercatorRadius)) / kDegToRad, x / kWebMercatorRadius / kDegToRad};
}

TileId wrap_tile(const TileId& t) {
  const int n = tiles_per_side(t.z);
  return {t.z, ((t.x % n) + n) % n, t.y};
}

MercatorBox tile_bounds(const TileId& t) {
  check_tile(t);
  const double span = tile_span(t.z), s = kWebMercatorOriginShift;
  return {-s + t.x * span, s - (t.y + 1) * span, -s + (t.x + 1) * span, s - t.y * span};
}

LonLatBox tile_lon_lat_bounds(const TileId& t) {
  const MercatorBox b = tile_bounds(t);
  const LatLon sw = mercator_to_lon_lat(b.xmin, b.ymin), ne = mercator_to_lon_lat(b.xmax, b.ymax);
  return {sw.longitude_deg, sw.latitude_deg, ne.longitude_deg, ne.latitude_deg};
}

TileId tile_at(double lon_deg, double lat_deg, int z) {
  const int n = tiles_per_side(z);
  const MercatorPoint p = lon_lat_to_mercator(lon_deg, lat_deg);
  const double span = tile_span(z), s = kWebMercatorOriginShift;
  return {z, clamp_index(std::floor(in_tiles(p.x + s, span)), n), clamp_index(std::floor(in_tiles(s - p.y, span)), n)};
}

TileRange tiles_covering(const MercatorBox& box, int z) {
  const int n = tiles_per_side(z);
  const double span = tile_span(z), s = kWebMercatorOriginShift;
  TileRange r;
  r.z = z;
  // A box from inside the world across its east edge goes on into the next copy of it
  // (a DEM across the antimeridian): at most one world wide, columns up to 2n − 1.
  const double xmin = std::max(box.xmin, -s);
  const bool wraps = box.xmin < s && box.xmax > s;
  const double xmax = std::min(box.xmax, wraps ? xmin + 2.0 * s : s);
  const double ymin = std::max(box.ymin, -s), ymax = std::min(box.ymax, s);
  if (!(xmin <= xmax && ymin <= ymax)) return r;  // outside the world (or NaN): empty
  // Tile columns: first holding xmin, last whose west edge is below xmax (half-open).
  const double fx0 = in_tiles(xmin + s, span), fx1 = in_tiles(xmax + s, span);
  const double fy0 = in_tiles(s - ymax, span), fy1 = in_tiles(s - ymin, span);
  r.x0 = clamp_index(std::floor(fx0), n);
  r.x1 = std::max(r.x0, wraps ? std::min(static_cast<int>(std::ceil(fx1)) - 1, r.x0 + n - 1)
                              : clamp_index(std::ceil(fx1) - 1.0, n));
  r.y0 = clamp_index(std::floor(fy0), n);
  r.y1 = std::max(r.y0, clamp_index(std::ceil(fy1) - 1.0, n));
  return r;
}

TileRange tiles_covering(const LonLatBox& box, int z) {
  const MercatorPoint sw = lon_lat_to_mercator(box.west, box.south), ne = lon_lat_to_mercator(box.east, box.north);
  return tiles_covering(MercatorBox{sw.x, sw.y, ne.x, ne.y}, z);
}

namespace {

// Whether the DEM's outline straddles the antimeridian: two samples along one edge,
// taken in −180…180°, more than 180° apart (`outline` holds the edges' samples
// interleaved, four per step, as dem_lon_lat_bounds makes them), or, in degrees,
// longitudes stored on both sides of ±180°.
bool crosses_antimeridian(const HeightField& dem, const std::vector<LatLon>& outline) {
  for (std::size_t k = 4; k < outline.size(); ++k)
    if (std::abs(outline[k].longitude_deg - outline[k - 4].longitude_deg) > 180.0) return true;
  if (!dem.georef.geographic) return false;
  const auto& gt = dem.georef.geotransform;
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const double c : {0.0, double(dem.width)})
    for (const double r : {0.0, double(dem.height)}) {
      const double lon = gt[0] + c * gt[1] + r * gt[2];
      low = std::min(low, lon), high = std::max(high, lon);
    }
  constexpr double kSlack = 1e-9;
  return (low < 180.0 - kSlack && high > 180.0 + kSlack) || (low < -180.0 - kSlack && high > -180.0 + kSlack);
}

}  // namespace

LonLatBox dem_lon_lat_bounds(const HeightField& dem) {
  std::vector<PixelPoint> edge;
  for (int k = 0; k <= kGridEdgeSamples; ++k) {
    const double f = static_cast<double>(k) / kGridEdgeSamples;
    const double c = f * dem.width, r = f * dem.height;
    edge.insert(edge.end(), {{c, 0.0}, {c, double(dem.height)}, {0.0, r}, {double(dem.width), r}});
  }
  const auto points = grid_points_lat_lon(dem.georef, edge);
  if (!points)
    throw DemError("the DEM has no " + std::string(dem.georef.crs_wkt.empty() ? "CRS" : "geotransform") +
                   ", so it cannot be placed on the web-map tile grid");
  // Across the antimeridian the outline is in one piece in 0…360°: east then runs past 180°.
  const bool crosses = crosses_antimeridian(dem, *points);
  LonLatBox box{360.0, 90.0, -180.0, -90.0};
  for (const LatLon& p : *points) {
    const double lon = crosses && p.longitude_deg < 0.0 ? p.longitude_deg + 360.0 : p.longitude_deg;
    box.west = std::min(box.west, lon);
    box.east = std::max(box.east, lon);
    box.south = std::min(box.south, p.latitude_deg);
    box.north = std::max(box.north, p.latitude_deg);
  }
  if (box.west >= 180.0) box.west -= 360.0, box.east -= 360.0;
  return box;
}

MercatorBox dem_mercator_bounds(const HeightField& dem) {
  const LonLatBox b = dem_lon_lat_bounds(dem);
  const MercatorPoint sw = lon_lat_to_mercator(b.west, b.south), ne = lon_lat_to_mercator(b.east, b.north);
  return {sw.x, sw.y, ne.x, ne.y};
}

int native_zoom(const HeightField& dem, int tile_size) {
  check_tile_size(tile_size);
  const std::optional<LatLon> centre = grid_centre_lat_lon(dem.georef, dem.width, dem.height);
  if (!centre)
    throw DemError("the DEM has no " + std::string(dem.georef.crs_wkt.empty() ? "CRS" : "geotransform") +
                   ", so it cannot be placed on the web-map tile grid");
  if (dem.height < 1 || static_cast<int>(dem.dx_per_row.size()) != dem.height)
    throw DemError("native zoom: the DEM's spacing has " + std::to_string(dem.dx_per_row.size()) +
                   " rows for a " + std::to_string(dem.height) + "-row grid");
  const double resolution = std::min(dem.dy, dem.dx(dem.height / 2));
  if (!(resolution > 0 && std::isfinite(resolution)))
    throw DemError("native zoom: the DEM's ground resolution is not a positive number");
  for (int z = 0; z < kMaxTileZoom; ++z)
    // The relative slack keeps a DEM exactly at a zoom's resolution on that zoom.
    if (ground_pixel_size(z, centre->latitude_deg, tile_size) <= resolution * (1.0 + 1e-12)) return z;
  return kMaxTileZoom;
}

ZoomRange default_zoom_range(int native) {
  check_zoom(native);
  return {std::max(0, native - 5), native};
}

}  // namespace skylit::terrain
