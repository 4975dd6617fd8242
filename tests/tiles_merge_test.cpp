// Merging shards of any kinds equals one uninterrupted run; conflicts fail before any
// output exists.
#include <gtest/gtest.h>

#include "tiles/merge.h"
#include "tiles_test_util.h"

namespace skylit::tiles {
namespace {

using namespace testing;

TileMetadata full_metadata() {
  auto m = sample_metadata();
  m.maxzoom = 4;
  return m;
}

class Shards : public ::testing::Test {
 protected:
  ScratchDir dir;
  Content all = pyramid(0, 4);
  std::vector<std::string> shards{dir.file("s0"), dir.file("s1.mbtiles"), dir.file("s2.pmtiles")};

  void SetUp() override {
    std::vector<Content> parts(3);
    int i = 0;
    for (const auto& [t, bytes] : all) parts[i++ % 3][t] = bytes;
    parts[1][{4, 0, 0}] = all[{4, 0, 0}];  // a border tile rendered by two shards, equal
    // Each shard's metadata covers its part; the merge widens them to the full run's.
    auto m0 = full_metadata(), m1 = full_metadata(), m2 = full_metadata();
    m0.bounds.east = 7.0;
    m1.bounds.west = 6.9;
    m1.minzoom = 1;
    m2.maxzoom = 3;
    write_archive(shards[0], parts[0], {}, m0);
    write_archive(shards[1], parts[1], {}, m1);
    write_archive(shards[2], parts[2], {}, m2);
  }
};

TEST_F(Shards, MergedPMTilesIsByteEqualToASingleRun) {
  const std::string single = dir.file("single.pmtiles"), merged = dir.file("merged.pmtiles");
  write_archive(single, all, {}, full_metadata());
  merge(shards, merged);
  EXPECT_EQ(file_bytes(merged), file_bytes(single));
  // The input order does not matter either.
  const std::string reversed = dir.file("reversed.pmtiles");
  merge({shards[2], shards[1], shards[0]}, reversed);
  EXPECT_EQ(read_content(reversed), all);
}

TEST_F(Shards, MergeIntoEachKind) {
  for (const char* name : {"m", "m.mbtiles", "m.pmtiles"}) {
    const std::string out = dir.file(name);
    merge(shards, out, {.scheme = Scheme::Tms});
    EXPECT_EQ(read_content(out), all) << name;
    EXPECT_EQ(open_reader(out)->metadata(), full_metadata()) << name;
  }
}

TEST_F(Shards, DifferentBytesForOneTileFailBeforeAnyOutput) {
  const std::string odd = dir.file("odd.mbtiles");
  write_archive(odd, {{{4, 0, 0}, "something else"}}, {}, full_metadata());
  const std::string out = dir.file("out.pmtiles");
  try {
    merge({shards[0], shards[1], shards[2], odd}, out);
    FAIL() << "merged conflicting shards";
  } catch (const TileArchiveError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("tile 4/0/0 differs"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos);
  }
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(out + ".partial"));
}

TEST_F(Shards, MixedFormatsFail) {
  const std::string webp = dir.file("w.pmtiles");
  write_archive(webp, {{{0, 0, 0}, "w"}}, {.format = TileFormat::Webp}, [] {
    auto m = full_metadata();
    m.format = TileFormat::Webp;
    return m;
  }());
  EXPECT_THROW(merge({shards[0], webp}, dir.file("out")), TileArchiveError);
  EXPECT_FALSE(fs::exists(dir.file("out")));
}

}  // namespace
}  // namespace skylit::tiles
