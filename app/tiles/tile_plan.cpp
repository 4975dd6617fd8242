#include "app/tiles/tile_plan.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <string>
#include <tuple>

namespace skylit::app::tiles {
namespace {

// Rows a window may have at this zoom before its single dy strays kMaxDyError from its
// rows' exact spacing: TileWindow's estimate sin φ · rows · π / (T · 2^z).
double max_window_rows(int z, int tile_size, double poleward_latitude_deg) {
  const double s = std::sin(std::abs(poleward_latitude_deg) * std::numbers::pi / 180.0);
  const double per_row = s * std::numbers::pi / (tile_size * static_cast<double>(terrain::tiles_per_side(z)));
  return per_row > 0 ? kMaxDyError / per_row : 1e300;
}

}  // namespace

ZoomPlan plan_zoom(const terrain::MercatorBox& dem_bounds, double poleward_latitude_deg, int z, int tile_size,
                   const HaloRequest& request) {
  ZoomPlan p;
  p.z = z;
  p.covering = terrain::tiles_covering(dem_bounds, z);
  const double g = terrain::ground_pixel_size(z, poleward_latitude_deg, tile_size);
  if (request.halo) {
    p.halo = *request.halo;
    if (p.halo <= kKernelMargin || p.halo > kMaxUserHalo)
      throw std::invalid_argument("--halo " + std::to_string(p.halo) + " is outside " + std::to_string(kKernelMargin + 1) +
                                  "…" + std::to_string(kMaxUserHalo) + " pixels");
    p.max_distance_m = (p.halo - kKernelMargin) * g;
    if (request.max_distance) p.max_distance_m = std::min(p.max_distance_m, *request.max_distance);
  } else if (request.max_distance) {
    const double h = horizon::halo_texels(*request.max_distance, g);
    if (h > kMaxUserHalo)
      throw std::invalid_argument("--max-distance " + std::to_string(*request.max_distance) + " needs a halo of " +
                                  std::to_string(static_cast<long long>(h)) + " pixels at zoom " + std::to_string(z) +
                                  " (at most " + std::to_string(kMaxUserHalo) + "): give a smaller distance or zoom");
    p.halo = static_cast<int>(h);
    p.max_distance_m = *request.max_distance;
  } else {
    const double h = horizon::halo_texels(kDefaultMaxDistanceM, g);
    p.halo = static_cast<int>(std::clamp(h, double(kMinHalo), double(kMaxHalo)));
    p.max_distance_m = std::min(kDefaultMaxDistanceM, (p.halo - kKernelMargin) * g);
  }
  p.block_columns = std::max(1, kBlockPixels / tile_size);
  const double rows = max_window_rows(z, tile_size, poleward_latitude_deg);
  p.block_rows = 1;
  while (p.block_rows * 2 <= p.block_columns && (p.block_rows * 2) * tile_size + 2 * p.halo <= rows) p.block_rows *= 2;
  return p;
}

namespace {

// [first, last] of part k of n near-equal parts of [lo, hi] (the first parts one longer).
std::pair<int, int> part(int lo, int hi, int n, int k) {
  const int count = hi - lo + 1, base = count / n, extra = count % n;
  const int first = lo + k * base + std::min(k, extra);
  return {first, first + base + (k < extra ? 1 : 0) - 1};
}

}  // namespace

std::vector<Block> blocks(const ZoomPlan& plan, int tile_size) {
  std::vector<Block> out;
  const terrain::TileRange& c = plan.covering;
  if (c.empty()) return out;
  // As few blocks as the sizes allow, of near-equal sides, from the covering range's
  // corner: each block pays two halos per side, so fewer and fuller blocks render less.
  const int nx = (c.columns() + plan.block_columns - 1) / plan.block_columns;
  const int ny = (c.rows() + plan.block_rows - 1) / plan.block_rows;
  for (int by = 0; by < ny; ++by)
    for (int bx = 0; bx < nx; ++bx) {
      const auto [x0, x1] = part(c.x0, c.x1, nx, bx);
      const auto [y0, y1] = part(c.y0, c.y1, ny, by);
      Block b;
      b.z = plan.z;
      b.column = bx;
      b.row = by;
      b.tiles = b.wanted = {plan.z, x0, y0, x1, y1};
      const double w = b.tiles.columns() * double(tile_size) + 2 * plan.halo;
      const double h = b.tiles.rows() * double(tile_size) + 2 * plan.halo;
      b.cost = w * h;
      out.push_back(b);
    }
  return out;
}

terrain::LonLatBox parse_bounds(const std::string& text) {
  const auto bad = [&](const std::string& why) {
    return std::invalid_argument("--bounds '" + text + "': " + why);
  };
  std::vector<double> v;
  std::size_t at = 0;
  while (v.size() < 5) {
    const std::size_t comma = text.find(',', at);
    const std::string part = text.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
    char* end = nullptr;
    const double x = std::strtod(part.c_str(), &end);
    if (part.empty() || end != part.c_str() + part.size() || !std::isfinite(x))
      throw bad("not W,S,E,N in degrees (e.g. -118.3,34.2,-117.9,34.4)");
    v.push_back(x);
    if (comma == std::string::npos) break;
    at = comma + 1;
  }
  if (v.size() != 4) throw bad("not W,S,E,N in degrees (e.g. -118.3,34.2,-117.9,34.4)");
  terrain::LonLatBox b{v[0], v[1], v[2], v[3]};
  if (std::abs(b.west) > 180 || std::abs(b.east) > 180) throw bad("longitudes run -180…180");
  if (std::abs(b.south) > 90 || std::abs(b.north) > 90) throw bad("latitudes run -90…90");
  if (!(b.south < b.north)) throw bad("the south edge is not below the north edge");
  if (b.west == b.east) throw bad("the box has no width");
  if (b.west > b.east) b.east += 360.0;  // across the antimeridian
  return b;
}

std::optional<terrain::LonLatBox> bounded_box(const terrain::LonLatBox& dem, const terrain::LonLatBox& bounds) {
  const double south = std::max(dem.south, bounds.south), north = std::min(dem.north, bounds.north);
  if (!(south < north)) return std::nullopt;
  for (const double shift : {0.0, -360.0, 360.0}) {  // the bounds in the DEM box's longitudes
    const double west = std::max(dem.west, bounds.west + shift), east = std::min(dem.east, bounds.east + shift);
    if (west < east) return terrain::LonLatBox{west, south, east, north};
  }
  return std::nullopt;
}

std::vector<Block> within(const std::vector<Block>& blocks, const terrain::LonLatBox& box) {
  // A box wholly past 180° (the east part of a DEM across the antimeridian) lies in the
  // world's next copy: its covering there is that of the box 360° west, 2^z columns on.
  const double shift = box.west >= 180.0 ? 360.0 : 0.0;
  const terrain::MercatorPoint sw = terrain::lon_lat_to_mercator(box.west - shift, box.south);
  const terrain::MercatorPoint ne = terrain::lon_lat_to_mercator(box.east - shift, box.north);
  std::vector<Block> out;
  for (Block b : blocks) {
    terrain::TileRange w = terrain::tiles_covering(terrain::MercatorBox{sw.x, sw.y, ne.x, ne.y}, b.z);
    if (shift > 0.0) w.x0 += terrain::tiles_per_side(b.z), w.x1 += terrain::tiles_per_side(b.z);
    b.wanted = {b.z, std::max(b.tiles.x0, w.x0), std::max(b.tiles.y0, w.y0), std::min(b.tiles.x1, w.x1),
                std::min(b.tiles.y1, w.y1)};
    if (!b.wanted.empty()) out.push_back(b);
  }
  return out;
}

Shard parse_shard(const std::string& text) {
  const auto bad = [&] {
    return std::invalid_argument("--shard '" + text + "' is not i/N with 1 ≤ i ≤ N (e.g. 1/4 … 4/4)");
  };
  const auto slash = text.find('/');
  if (slash == std::string::npos) throw bad();
  const auto number = [&](const std::string& s) {
    if (s.empty() || s.size() > 9 || !std::all_of(s.begin(), s.end(), [](char ch) { return ch >= '0' && ch <= '9'; }))
      throw bad();
    return std::stoi(s);
  };
  Shard s{number(text.substr(0, slash)), number(text.substr(slash + 1))};
  if (s.count < 1 || s.index < 1 || s.index > s.count) throw bad();
  return s;
}

std::vector<Block> shard_blocks(const std::vector<Block>& all, const Shard& shard) {
  std::vector<std::size_t> order(all.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const Block &x = all[a], &y = all[b];
    if (x.cost != y.cost) return x.cost > y.cost;
    return std::tie(x.z, x.row, x.column) < std::tie(y.z, y.row, y.column);
  });
  std::vector<double> load(static_cast<std::size_t>(shard.count), 0.0);
  std::vector<bool> mine(all.size(), false);
  for (std::size_t k : order) {
    const auto least = std::min_element(load.begin(), load.end()) - load.begin();  // first of equals
    load[static_cast<std::size_t>(least)] += all[k].cost;
    mine[k] = least == shard.index - 1;
  }
  std::vector<Block> out;
  for (std::size_t k = 0; k < all.size(); ++k)
    if (mine[k]) out.push_back(all[k]);
  return out;
}

}  // namespace skylit::app::tiles
