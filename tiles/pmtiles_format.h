// The byte-level pieces of PMTiles v3 (protomaps/PMTiles spec/v3/spec.md): tile ids on
// Hilbert curves, varints, directories, the 127-byte header, gzip. No I/O here, so
// tests can check each piece against the spec's own numbers.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tiles/archive.h"
#include "tiles/metadata.h"

namespace skylit::tiles::pmtiles {

inline constexpr std::size_t kHeaderBytes = 127;
// The header plus the compressed root directory must fit the first 16 KiB (spec §4).
inline constexpr std::size_t kRootRegionBytes = 16384;

enum class Compression : std::uint8_t { Unknown = 0, None = 1, Gzip = 2, Brotli = 3, Zstd = 4 };
enum class TileType : std::uint8_t { Unknown = 0, Mvt = 1, Png = 2, Jpeg = 3, Webp = 4, Avif = 5 };

TileType tile_type(TileFormat f);

// Position on the cumulative series of Hilbert curves: (4^z − 1)/3 tiles precede zoom z,
// then the index of (x, y) on zoom z's curve.
std::uint64_t tile_id(const TileId& t);
TileId tile_of(std::uint64_t id);  // inverse of tile_id()

// Protobuf-style unsigned varints, 7 bits per byte, least significant first.
void write_varint(std::string& out, std::uint64_t v);
// Reads at `pos`, advancing it; throws TileArchiveError past the end or beyond 64 bits.
std::uint64_t read_varint(std::string_view in, std::size_t& pos);

struct Entry {
  std::uint64_t tile_id = 0;
  std::uint64_t offset = 0;  // in the tile data (tiles) or leaf section (leaves)
  std::uint32_t length = 0;
  std::uint32_t run_length = 0;  // 0: a leaf directory
  friend bool operator==(const Entry&, const Entry&) = default;
};

// Uncompressed directory bytes (spec §4.2): count, id deltas, run lengths, lengths,
// offsets as offset + 1 or 0 when contiguous with the previous entry.
std::string encode_directory(std::span<const Entry> entries);
std::vector<Entry> decode_directory(std::string_view bytes);

std::string gzip(std::string_view data);
std::string gunzip(std::string_view data);  // throws TileArchiveError on bad data

struct Header {
  std::uint64_t root_offset = 0, root_length = 0;
  std::uint64_t metadata_offset = 0, metadata_length = 0;
  std::uint64_t leaves_offset = 0, leaves_length = 0;
  std::uint64_t data_offset = 0, data_length = 0;
  std::uint64_t addressed_tiles = 0, tile_entries = 0, tile_contents = 0;
  bool clustered = true;
  Compression internal_compression = Compression::Gzip;
  Compression tile_compression = Compression::None;
  TileType tile_type = TileType::Unknown;
  std::uint8_t min_zoom = 0, max_zoom = 0;
  std::int32_t min_lon_e7 = 0, min_lat_e7 = 0, max_lon_e7 = 0, max_lat_e7 = 0;
  std::uint8_t center_zoom = 0;
  std::int32_t center_lon_e7 = 0, center_lat_e7 = 0;
  friend bool operator==(const Header&, const Header&) = default;
};

std::string encode_header(const Header& h);   // exactly kHeaderBytes
Header decode_header(std::string_view bytes);  // throws unless magic "PMTiles" and version 3

std::int32_t to_e7(double degrees);

// The root directory and the leaf section for sorted tile entries: everything in the
// root when its gzip fits `max_root_bytes`, else leaves of n entries each (n doubling
// until the root of leaf pointers fits).
struct Directories {
  std::string root;    // compressed
  std::string leaves;  // compressed leaf directories, back to back
};
Directories build_directories(std::span<const Entry> entries, std::size_t max_root_bytes,
                              std::size_t first_leaf_entries = 4096);

}  // namespace skylit::tiles::pmtiles
