// A map tile's address in the XYZ convention (Web Mercator, x east from 180°W, y down
// from the north edge), the one every writer and reader of this library takes; TMS rows
// and PMTiles' Hilbert ids are derived from it where a format needs them.
#pragma once

#include <cstdint>
#include <string>

namespace skylit::tiles {

// Deepest zoom the library accepts: 2^31 columns still fit x and y, and the PMTiles id
// of every tile up to it fits 64 bits ((4^32 − 1)/3 < 2^64).
inline constexpr int kMaxZoom = 31;

struct TileId {
  int z = 0;
  std::uint32_t x = 0, y = 0;
  friend bool operator==(const TileId&, const TileId&) = default;
  friend auto operator<=>(const TileId&, const TileId&) = default;
};

// Tiles per axis at zoom z (2^z).
constexpr std::uint64_t tiles_per_axis(int z) { return std::uint64_t{1} << z; }

// 0 ≤ z ≤ kMaxZoom and x, y < 2^z.
constexpr bool is_valid(const TileId& t) {
  return t.z >= 0 && t.z <= kMaxZoom && t.x < tiles_per_axis(t.z) && t.y < tiles_per_axis(t.z);
}

// The TMS row of an XYZ row (TMS counts y up from the south edge); its own inverse.
constexpr std::uint32_t flip_row(int z, std::uint32_t y) {
  return static_cast<std::uint32_t>(tiles_per_axis(z) - 1 - y);
}

// "z/x/y", for messages.
std::string to_string(const TileId& t);

}  // namespace skylit::tiles
