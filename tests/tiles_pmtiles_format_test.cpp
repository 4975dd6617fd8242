// PMTiles v3 byte-level pieces against the spec (protomaps/PMTiles spec/v3/spec.md) and
// values worked out by hand, not against the writer's own output.
#include <gtest/gtest.h>

#include <cstdlib>
#include <random>

#include "tiles/archive.h"
#include "tiles/pmtiles_format.h"
#include "tiles_test_util.h"

namespace skylit::tiles::pmtiles {
namespace {

using testing::ScratchDir;

std::string bytes(std::initializer_list<int> v) {
  std::string s;
  for (int b : v) s.push_back(static_cast<char>(b));
  return s;
}

TEST(Hilbert, MatchesTheSpecTable) {
  EXPECT_EQ(tile_id({0, 0, 0}), 0u);
  // z1 in Hilbert order: down the west column, then up the east one.
  EXPECT_EQ(tile_id({1, 0, 0}), 1u);
  EXPECT_EQ(tile_id({1, 0, 1}), 2u);
  EXPECT_EQ(tile_id({1, 1, 1}), 3u);
  EXPECT_EQ(tile_id({1, 1, 0}), 4u);
  EXPECT_EQ(tile_id({2, 0, 0}), 5u);
  EXPECT_EQ(tile_id({12, 3423, 1763}), 19078479u);  // the spec's last row
}

TEST(Hilbert, FirstIdOfEachZoomIsTheCountOfShallowerTiles) {
  std::uint64_t before = 0;  // 1 + 4 + … + 4^(n−1) = (4^n − 1)/3, summed by hand here
  for (int z = 0; z <= terrain::kMaxTileZoom; ++z) {
    EXPECT_EQ(tile_id({z, 0, 0}), before) << "z=" << z;
    before += std::uint64_t{1} << (2 * z);
  }
  EXPECT_EQ(tile_id({3, 0, 0}), 21u);
  EXPECT_EQ(tile_id({12, 0, 0}), 5592405u);
}

TEST(Hilbert, ZoomTwoInCurveOrder) {
  // The order-2 curve drawn by hand from the z1 orientation: each quadrant a rotated
  // copy of the z1 "U", entered at (0,0) and left at (3,0).
  const std::vector<std::pair<int, int>> order{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 2}, {0, 3},
                                               {1, 3}, {1, 2}, {2, 2}, {2, 3}, {3, 3}, {3, 2},
                                               {3, 1}, {2, 1}, {2, 0}, {3, 0}};
  for (std::size_t d = 0; d < order.size(); ++d) {
    const TileId t{2, order[d].first, order[d].second};
    EXPECT_EQ(tile_id(t), 5 + d) << to_string(t);
    EXPECT_EQ(tile_of(5 + d), t);
  }
}

TEST(Hilbert, ConsecutiveIdsAreNeighboursAndTheInverseHolds) {
  for (int z = 1; z <= 6; ++z) {
    const std::uint64_t first = tile_id({z, 0, 0}), n = std::uint64_t{1} << (2 * z);
    std::vector<bool> seen(n);
    TileId prev = tile_of(first);
    for (std::uint64_t id = first; id < first + n; ++id) {
      const TileId t = tile_of(id);
      ASSERT_EQ(t.z, z);
      ASSERT_EQ(tile_id(t), id);
      seen[t.x * (1u << z) + t.y] = true;
      if (id > first) {
        const auto dx = std::abs(static_cast<long>(t.x) - static_cast<long>(prev.x));
        const auto dy = std::abs(static_cast<long>(t.y) - static_cast<long>(prev.y));
        ASSERT_EQ(dx + dy, 1) << "ids " << id - 1 << ", " << id;
      }
      prev = t;
    }
    EXPECT_EQ(std::count(seen.begin(), seen.end(), true), static_cast<long>(n));
  }
  std::mt19937_64 rng(7);
  for (int i = 0; i < 1000; ++i) {
    const int z = static_cast<int>(rng() % (terrain::kMaxTileZoom + 1));
    const TileId t{z, static_cast<int>(rng() % (1ull << z)), static_cast<int>(rng() % (1ull << z))};
    ASSERT_EQ(tile_of(tile_id(t)), t) << to_string(t);
  }
}

TEST(Varint, KnownEncodings) {
  const auto enc = [](std::uint64_t v) {
    std::string s;
    write_varint(s, v);
    return s;
  };
  EXPECT_EQ(enc(0), bytes({0x00}));
  EXPECT_EQ(enc(1), bytes({0x01}));
  EXPECT_EQ(enc(127), bytes({0x7f}));
  EXPECT_EQ(enc(128), bytes({0x80, 0x01}));
  EXPECT_EQ(enc(150), bytes({0x96, 0x01}));  // protobuf encoding guide's example
  EXPECT_EQ(enc(300), bytes({0xac, 0x02}));
  EXPECT_EQ(enc(~std::uint64_t{0}), bytes({0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0x01}));
  for (std::uint64_t v : {0ull, 300ull, ~0ull}) {
    std::size_t pos = 0;
    EXPECT_EQ(read_varint(enc(v), pos), v);
    EXPECT_EQ(pos, enc(v).size());
  }
  std::size_t pos = 0;
  EXPECT_THROW(read_varint(bytes({0x80}), pos), TileArchiveError);
}

TEST(Directory, EncodingByHand) {
  // Tile 5, tiles 6–8 (one run) right after it, and tile 20 reusing tile 5's bytes.
  const std::vector<Entry> e{{5, 0, 42, 1}, {6, 42, 10, 3}, {20, 0, 42, 1}};
  // count; id deltas 5, 1, 14; runs 1, 3, 1; lengths 42, 10, 42;
  // offsets 0+1, 0 (contiguous: 42 = 0 + 42), 0+1 (not contiguous: 0 ≠ 52).
  const std::string want = bytes({3, 5, 1, 14, 1, 3, 1, 42, 10, 42, 1, 0, 1});
  EXPECT_EQ(encode_directory(e), want);
  EXPECT_EQ(decode_directory(want), e);
}

TEST(Gzip, IsRealGzip) {
  ScratchDir dir;
  const std::string text = "PMTiles directories are gzip-compressed " + std::string(1000, 'x');
  const std::string z = gzip(text);
  EXPECT_EQ(z.substr(0, 2), bytes({0x1f, 0x8b}));
  EXPECT_LT(z.size(), text.size());
  EXPECT_EQ(gunzip(z), text);
  { std::ofstream(dir.path() / "t.gz", std::ios::binary) << z; }
  EXPECT_EQ(testing::shell("gzip -dc '" + (dir.path() / "t.gz").string() + "'"), text);
  EXPECT_THROW(gunzip("not gzip"), TileArchiveError);
}

TEST(Header, FieldsAtTheSpecsOffsets) {
  Header h;
  h.root_offset = 127;
  h.root_length = 0x0102;
  h.metadata_offset = 0x0304;
  h.metadata_length = 0x0506;
  h.leaves_offset = 0x0708;
  h.leaves_length = 0x090a;
  h.data_offset = 0x0b0c;
  h.data_length = 0x0d0e0f;
  h.addressed_tiles = 11;
  h.tile_entries = 12;
  h.tile_contents = 13;
  h.tile_type = TileType::Webp;
  h.min_zoom = 2;
  h.max_zoom = 14;
  h.min_lon_e7 = to_e7(-122.5);
  h.min_lat_e7 = to_e7(37.25);
  h.max_lon_e7 = to_e7(-121.75);
  h.max_lat_e7 = to_e7(38.0);
  h.center_zoom = 9;
  h.center_lon_e7 = to_e7(-122.125);
  h.center_lat_e7 = to_e7(37.625);
  const std::string b = encode_header(h);
  ASSERT_EQ(b.size(), 127u);
  using testing::le;
  EXPECT_EQ(b.substr(0, 7), "PMTiles");
  EXPECT_EQ(b[7], 3);
  EXPECT_EQ(le(b, 0x08, 8), 127u);
  EXPECT_EQ(le(b, 0x10, 8), 0x0102u);
  EXPECT_EQ(le(b, 0x18, 8), 0x0304u);
  EXPECT_EQ(le(b, 0x20, 8), 0x0506u);
  EXPECT_EQ(le(b, 0x28, 8), 0x0708u);
  EXPECT_EQ(le(b, 0x30, 8), 0x090au);
  EXPECT_EQ(le(b, 0x38, 8), 0x0b0cu);
  EXPECT_EQ(le(b, 0x40, 8), 0x0d0e0fu);
  EXPECT_EQ(le(b, 0x48, 8), 11u);
  EXPECT_EQ(le(b, 0x50, 8), 12u);
  EXPECT_EQ(le(b, 0x58, 8), 13u);
  EXPECT_EQ(b[0x60], 1);  // clustered
  EXPECT_EQ(b[0x61], 2);  // internal compression gzip
  EXPECT_EQ(b[0x62], 1);  // tile compression none
  EXPECT_EQ(b[0x63], 4);  // webp
  EXPECT_EQ(b[0x64], 2);
  EXPECT_EQ(b[0x65], 14);
  EXPECT_EQ(static_cast<std::int32_t>(le(b, 0x66, 4)), -1225000000);
  EXPECT_EQ(static_cast<std::int32_t>(le(b, 0x6a, 4)), 372500000);
  EXPECT_EQ(static_cast<std::int32_t>(le(b, 0x6e, 4)), -1217500000);
  EXPECT_EQ(static_cast<std::int32_t>(le(b, 0x72, 4)), 380000000);
  EXPECT_EQ(b[0x76], 9);
  EXPECT_EQ(static_cast<std::int32_t>(le(b, 0x77, 4)), -1221250000);
  EXPECT_EQ(static_cast<std::int32_t>(le(b, 0x7b, 4)), 376250000);
  EXPECT_EQ(decode_header(b), h);
  EXPECT_THROW(decode_header("PMTiles\x02" + b.substr(8)), TileArchiveError);
}

TEST(Directories, LeavesWhenTheRootWouldNotFit) {
  std::vector<Entry> entries;
  std::uint64_t offset = 0;
  std::mt19937 rng(3);
  for (std::uint64_t id = 0; id < 2000; id += 1 + rng() % 3) {
    const auto len = static_cast<std::uint32_t>(1 + rng() % 5000);
    entries.push_back({id, offset, len, 1});
    offset += len;
  }
  const Directories all = build_directories(entries, 1 << 20);
  EXPECT_TRUE(all.leaves.empty());
  EXPECT_EQ(decode_directory(gunzip(all.root)), entries);

  const Directories d = build_directories(entries, 200, 32);
  ASSERT_FALSE(d.leaves.empty());
  EXPECT_LE(d.root.size(), 200u);
  const auto root = decode_directory(gunzip(d.root));
  ASSERT_GT(root.size(), 1u);
  std::vector<Entry> from_leaves;
  std::uint64_t next = 0;
  for (const auto& leaf : root) {
    EXPECT_EQ(leaf.run_length, 0u);  // a leaf pointer
    EXPECT_EQ(leaf.offset, next);    // leaves back to back, in id order
    next += leaf.length;
    const auto part = decode_directory(gunzip(d.leaves.substr(leaf.offset, leaf.length)));
    EXPECT_EQ(part.front().tile_id, leaf.tile_id);
    from_leaves.insert(from_leaves.end(), part.begin(), part.end());
  }
  EXPECT_EQ(next, d.leaves.size());
  EXPECT_EQ(from_leaves, entries);
}

}  // namespace
}  // namespace skylit::tiles::pmtiles
