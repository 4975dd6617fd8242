#include "tiles/pmtiles_format.h"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

#include "tiles/archive.h"

namespace skylit::tiles::pmtiles {
namespace {

[[noreturn]] void bad(const std::string& what) { throw TileArchiveError("PMTiles: " + what); }

constexpr std::string_view kMagic = "PMTiles";
constexpr std::uint8_t kVersion = 3;

// Tiles per axis at zoom z, in the 64 bits Hilbert arithmetic needs.
std::uint64_t side(int z) { return std::uint64_t{1} << z; }

std::uint64_t tiles_before(int z) { return ((std::uint64_t{1} << (2 * z)) - 1) / 3; }

// Hilbert-curve rotation of the quadrant (Wikipedia "Hilbert curve", xy2d / d2xy).
void rotate(std::uint64_t n, std::uint64_t& x, std::uint64_t& y, std::uint64_t rx, std::uint64_t ry) {
  if (ry == 0) {
    if (rx == 1) {
      x = n - 1 - x;
      y = n - 1 - y;
    }
    std::swap(x, y);
  }
}

void put_le(std::string& out, std::uint64_t v, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
}

std::uint64_t get_le(std::string_view in, std::size_t at, int bytes) {
  std::uint64_t v = 0;
  for (int i = 0; i < bytes; ++i)
    v |= std::uint64_t{static_cast<unsigned char>(in[at + i])} << (8 * i);
  return v;
}

}  // namespace

TileType tile_type(TileFormat f) {
  switch (f) {
    case TileFormat::Png: return TileType::Png;
    case TileFormat::Jpeg: return TileType::Jpeg;
    case TileFormat::Webp: return TileType::Webp;
  }
  return TileType::Unknown;
}

std::uint64_t tile_id(const TileId& t) {
  if (!is_valid(t)) bad("tile " + to_string(t) + " is outside its zoom's grid");
  const std::uint64_t n = side(t.z);
  std::uint64_t x = t.x, y = t.y, d = 0;
  for (std::uint64_t s = n / 2; s > 0; s /= 2) {
    const std::uint64_t rx = (x & s) ? 1 : 0, ry = (y & s) ? 1 : 0;
    d += s * s * ((3 * rx) ^ ry);
    rotate(n, x, y, rx, ry);
  }
  return tiles_before(t.z) + d;
}

TileId tile_of(std::uint64_t id) {
  int z = 0;
  while (z < terrain::kMaxTileZoom && id >= tiles_before(z + 1)) ++z;
  std::uint64_t t = id - tiles_before(z);
  if (t >= side(z) * side(z)) bad("tile id " + std::to_string(id) + " is too deep");
  std::uint64_t x = 0, y = 0;
  for (std::uint64_t s = 1; s < side(z); s *= 2) {
    const std::uint64_t rx = 1 & (t / 2), ry = 1 & (t ^ rx);
    rotate(s, x, y, rx, ry);
    x += s * rx;
    y += s * ry;
    t /= 4;
  }
  return {z, static_cast<int>(x), static_cast<int>(y)};
}

void write_varint(std::string& out, std::uint64_t v) {
  while (v >= 0x80) {
    out.push_back(static_cast<char>((v & 0x7f) | 0x80));
    v >>= 7;
  }
  out.push_back(static_cast<char>(v));
}

std::uint64_t read_varint(std::string_view in, std::size_t& pos) {
  std::uint64_t v = 0;
  for (int shift = 0; shift < 64; shift += 7) {
    if (pos >= in.size()) bad("directory ends inside a varint");
    const auto b = static_cast<unsigned char>(in[pos++]);
    v |= std::uint64_t{b & 0x7fu} << shift;
    if (!(b & 0x80)) return v;
  }
  bad("varint longer than 64 bits");
}

std::string encode_directory(std::span<const Entry> entries) {
  std::string out;
  write_varint(out, entries.size());
  std::uint64_t last_id = 0;
  for (const auto& e : entries) {
    write_varint(out, e.tile_id - last_id);
    last_id = e.tile_id;
  }
  for (const auto& e : entries) write_varint(out, e.run_length);
  for (const auto& e : entries) write_varint(out, e.length);
  std::uint64_t next = 0;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const auto& e = entries[i];
    write_varint(out, i > 0 && e.offset == next ? 0 : e.offset + 1);
    next = e.offset + e.length;
  }
  return out;
}

std::vector<Entry> decode_directory(std::string_view in) {
  std::size_t pos = 0;
  const std::uint64_t n = read_varint(in, pos);
  if (n == 0 || n > in.size()) bad("directory entry count " + std::to_string(n) + " is implausible");
  std::vector<Entry> entries(n);
  std::uint64_t id = 0;
  for (auto& e : entries) e.tile_id = id += read_varint(in, pos);
  for (auto& e : entries) e.run_length = static_cast<std::uint32_t>(read_varint(in, pos));
  for (auto& e : entries) e.length = static_cast<std::uint32_t>(read_varint(in, pos));
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint64_t v = read_varint(in, pos);
    if (v == 0 && i > 0)
      entries[i].offset = entries[i - 1].offset + entries[i - 1].length;
    else if (v == 0)
      bad("the first directory entry has no offset");
    else
      entries[i].offset = v - 1;
  }
  return entries;
}

std::string gzip(std::string_view data) {
  z_stream zs{};
  // windowBits 15 + 16: a gzip wrapper (zlib writes mtime 0, so equal input gives equal bytes).
  if (deflateInit2(&zs, Z_BEST_COMPRESSION, Z_DEFLATED, 15 + 16, 9, Z_DEFAULT_STRATEGY) != Z_OK)
    bad("cannot start gzip");
  std::string out(deflateBound(&zs, data.size()) + 32, '\0');
  zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  zs.avail_in = static_cast<uInt>(data.size());
  zs.next_out = reinterpret_cast<Bytef*>(out.data());
  zs.avail_out = static_cast<uInt>(out.size());
  const int rc = deflate(&zs, Z_FINISH);
  out.resize(zs.total_out);
  deflateEnd(&zs);
  if (rc != Z_STREAM_END) bad("gzip failed");
  return out;
}

std::string gunzip(std::string_view data) {
  z_stream zs{};
  if (inflateInit2(&zs, 15 + 16) != Z_OK) bad("cannot start gunzip");
  zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  zs.avail_in = static_cast<uInt>(data.size());
  std::string out;
  char buf[1 << 15];
  int rc = Z_OK;
  while (rc == Z_OK) {
    zs.next_out = reinterpret_cast<Bytef*>(buf);
    zs.avail_out = sizeof buf;
    rc = inflate(&zs, Z_NO_FLUSH);
    out.append(buf, sizeof buf - zs.avail_out);
    if (rc == Z_BUF_ERROR && zs.avail_in == 0) break;
  }
  inflateEnd(&zs);
  if (rc != Z_STREAM_END) bad("bad gzip data");
  return out;
}

std::int32_t to_e7(double degrees) { return static_cast<std::int32_t>(std::lround(degrees * 1e7)); }

std::string encode_header(const Header& h) {
  std::string out(kMagic);
  out.push_back(static_cast<char>(kVersion));
  for (std::uint64_t v : {h.root_offset, h.root_length, h.metadata_offset, h.metadata_length,
                          h.leaves_offset, h.leaves_length, h.data_offset, h.data_length,
                          h.addressed_tiles, h.tile_entries, h.tile_contents})
    put_le(out, v, 8);
  for (std::uint8_t v : {std::uint8_t{h.clustered}, static_cast<std::uint8_t>(h.internal_compression),
                         static_cast<std::uint8_t>(h.tile_compression),
                         static_cast<std::uint8_t>(h.tile_type), h.min_zoom, h.max_zoom})
    out.push_back(static_cast<char>(v));
  for (std::int32_t v : {h.min_lon_e7, h.min_lat_e7, h.max_lon_e7, h.max_lat_e7})
    put_le(out, static_cast<std::uint32_t>(v), 4);
  out.push_back(static_cast<char>(h.center_zoom));
  put_le(out, static_cast<std::uint32_t>(h.center_lon_e7), 4);
  put_le(out, static_cast<std::uint32_t>(h.center_lat_e7), 4);
  return out;
}

Header decode_header(std::string_view in) {
  if (in.size() < kHeaderBytes || in.substr(0, kMagic.size()) != kMagic) bad("not a PMTiles archive");
  if (static_cast<std::uint8_t>(in[7]) != kVersion)
    bad("version " + std::to_string(static_cast<int>(in[7])) + " is not 3");
  Header h;
  std::size_t at = 8;
  for (std::uint64_t* v : {&h.root_offset, &h.root_length, &h.metadata_offset, &h.metadata_length,
                           &h.leaves_offset, &h.leaves_length, &h.data_offset, &h.data_length,
                           &h.addressed_tiles, &h.tile_entries, &h.tile_contents}) {
    *v = get_le(in, at, 8);
    at += 8;
  }
  const auto byte = [&] { return static_cast<std::uint8_t>(in[at++]); };
  h.clustered = byte() == 1;
  h.internal_compression = static_cast<Compression>(byte());
  h.tile_compression = static_cast<Compression>(byte());
  h.tile_type = static_cast<TileType>(byte());
  h.min_zoom = byte();
  h.max_zoom = byte();
  const auto i32 = [&] {
    const auto v = static_cast<std::int32_t>(static_cast<std::uint32_t>(get_le(in, at, 4)));
    at += 4;
    return v;
  };
  h.min_lon_e7 = i32();
  h.min_lat_e7 = i32();
  h.max_lon_e7 = i32();
  h.max_lat_e7 = i32();
  h.center_zoom = byte();
  h.center_lon_e7 = i32();
  h.center_lat_e7 = i32();
  return h;
}

Directories build_directories(std::span<const Entry> entries, std::size_t max_root_bytes,
                              std::size_t first_leaf_entries) {
  if (entries.empty()) bad("an archive needs at least one tile");
  Directories d{gzip(encode_directory(entries)), {}};
  if (d.root.size() <= max_root_bytes) return d;
  for (std::size_t n = std::max<std::size_t>(first_leaf_entries, 1);; n *= 2) {
    std::vector<Entry> root;
    d.leaves.clear();
    for (std::size_t i = 0; i < entries.size(); i += n) {
      const auto leaf = gzip(encode_directory(entries.subspan(i, std::min(n, entries.size() - i))));
      root.push_back({entries[i].tile_id, d.leaves.size(), static_cast<std::uint32_t>(leaf.size()), 0});
      d.leaves += leaf;
    }
    d.root = gzip(encode_directory(root));
    if (d.root.size() <= max_root_bytes) return d;
    if (root.size() == 1) bad("a root directory of one leaf exceeds " + std::to_string(max_root_bytes) + " bytes");
  }
}

}  // namespace skylit::tiles::pmtiles
