// Writing and reading back each archive kind: round trips, the kind chosen by the
// path, the modes, MBTiles checked with the sqlite3 CLI, PMTiles' header by offset,
// deduplication, run lengths and leaf directories.
#include <gtest/gtest.h>

#include "tiles/archive.h"
#include "tiles/pmtiles_format.h"
#include "tiles/reader.h"
#include "tiles_test_util.h"

namespace skylit::tiles {
namespace {

using namespace testing;

const char* const kKinds[] = {"out", "out.mbtiles", "out.pmtiles"};

class EachKind : public ::testing::TestWithParam<const char*> {
 protected:
  ScratchDir dir;
  std::string out = dir.file(GetParam());
};

TEST_P(EachKind, RoundTripsTilesAndMetadata) {
  const Content c = pyramid(0, 3);
  write_archive(out, c);
  EXPECT_EQ(read_content(out), c);
  const auto r = open_reader(out);
  EXPECT_EQ(r->metadata(), sample_metadata());
  EXPECT_EQ(r->get({3, 0, 1}), payload({3, 0, 1}));
  EXPECT_FALSE(r->get({4, 0, 0}).has_value());
  EXPECT_EQ(dir.listing(), std::vector<std::string>{GetParam()});  // no staging left behind
}

TEST_P(EachKind, CreateRefusesAnExistingOutputOverwriteReplacesIt) {
  write_archive(out, pyramid(0, 1));
  try {
    open_archive(out);
    FAIL() << "created over an existing archive";
  } catch (const TileArchiveError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("exists"), std::string::npos) << e.what();
    EXPECT_EQ(e.option(), "overwrite");
  }
  EXPECT_EQ(read_content(out), pyramid(0, 1));  // untouched
  const Content two = pyramid(2, 2);
  write_archive(out, two, {.mode = OpenMode::Overwrite});
  EXPECT_EQ(read_content(out), two);
}

TEST_P(EachKind, HasSeesOnlyWhatWasPut) {
  auto a = open_archive(out);
  EXPECT_FALSE(a->has({1, 1, 0}));
  a->put({1, 1, 0}, as_bytes(std::string("x")));
  EXPECT_TRUE(a->has({1, 1, 0}));
  EXPECT_FALSE(a->has({1, 0, 1}));
  EXPECT_FALSE(a->has({1, 2, 0}));  // outside the grid: never there
  EXPECT_THROW(a->put({1, 2, 0}, as_bytes(std::string("x"))), TileArchiveError);
  EXPECT_THROW(a->put({1, 0, 0}, {}), TileArchiveError);
}

TEST_P(EachKind, ResumeKeepsAFinishedRunsTiles) {
  write_archive(out, pyramid(0, 1));
  auto a = open_archive(out, {.mode = OpenMode::Resume});
  EXPECT_TRUE(a->has({1, 1, 1}));
  EXPECT_FALSE(a->has({2, 0, 0}));
  write_all(*a, pyramid(2, 2));
  a->finish(sample_metadata());
  Content want = pyramid(0, 2);
  EXPECT_EQ(read_content(out), want);
}

TEST_P(EachKind, FinishChecksTheMetadata) {
  auto a = open_archive(out);
  a->put({0, 0, 0}, as_bytes(std::string("x")));
  TileMetadata m = sample_metadata();
  m.minzoom = 5;
  m.maxzoom = 4;
  EXPECT_THROW(a->finish(m), TileArchiveError);
  m = sample_metadata(TileFormat::Webp);  // opened as png
  EXPECT_THROW(a->finish(m), TileArchiveError);
  a->finish(sample_metadata());
  EXPECT_THROW(a->put({0, 0, 0}, as_bytes(std::string("y"))), TileArchiveError);
}

INSTANTIATE_TEST_SUITE_P(Kinds, EachKind, ::testing::ValuesIn(kKinds),
                         [](const auto& info) {
                           std::string s = info.param;
                           return s == "out" ? std::string("folder") : s.substr(4);
                         });

TEST(ArchiveKind, FromThePath) {
  EXPECT_EQ(archive_kind("a/b.mbtiles"), ArchiveKind::MBTiles);
  EXPECT_EQ(archive_kind("B.PMTiles"), ArchiveKind::PMTiles);
  EXPECT_EQ(archive_kind("tiles"), ArchiveKind::Folder);
  EXPECT_EQ(archive_kind("tiles.v2/"), ArchiveKind::Folder);
  try {
    archive_kind("out.zip");
    FAIL();
  } catch (const TileArchiveError& e) {
    EXPECT_STREQ(e.what(),
                 "'out.zip': unknown tile archive kind '.zip' (use .mbtiles, .pmtiles, or a folder "
                 "name without an extension)");
  }
  ScratchDir dir;
  EXPECT_THROW(open_archive(dir.file("out.zip")), TileArchiveError);
  EXPECT_TRUE(dir.listing().empty());
}

TEST(Reader, MissingOrUnfinishedArchivesFailInOneLine) {
  ScratchDir dir;
  for (const char* name : {"none", "none.mbtiles", "none.pmtiles"}) {
    try {
      open_reader(dir.file(name));
      FAIL() << name;
    } catch (const TileArchiveError& e) {
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    }
  }
  { std::ofstream(dir.path() / "junk.pmtiles") << "not an archive"; }
  EXPECT_THROW(open_reader(dir.file("junk.pmtiles")), TileArchiveError);
  { std::ofstream(dir.path() / "junk.mbtiles") << "not a database"; }
  EXPECT_THROW(open_archive(dir.file("junk.mbtiles"), {.mode = OpenMode::Resume}), TileArchiveError);
}

TEST(Folder, XyzAndTmsPaths) {
  ScratchDir dir;
  const Content c = pyramid(2, 2);
  write_archive(dir.file("xyz"), c, {.format = TileFormat::Webp}, sample_metadata(TileFormat::Webp));
  write_archive(dir.file("tms"), c, {.scheme = Scheme::Tms});
  // z2, x1, y0 (north row): XYZ file 0, TMS file 2^2 − 1 − 0 = 3.
  EXPECT_EQ(file_bytes(dir.path() / "xyz/2/1/0.webp"), payload({2, 1, 0}));
  EXPECT_EQ(file_bytes(dir.path() / "tms/2/1/3.png"), payload({2, 1, 0}));
  EXPECT_EQ(file_bytes(dir.path() / "tms/2/1/0.png"), payload({2, 1, 3}));
  EXPECT_EQ(read_content(dir.file("tms")), c);
  EXPECT_NE(fs::status(dir.path() / "tms/2/1/3.png").permissions() & fs::perms::others_read,
            fs::perms::none);  // servable, not mkstemp's 0600
  const std::string meta = file_bytes(dir.path() / "tms/metadata.json");
  EXPECT_NE(meta.find("\"scheme\":\"tms\""), std::string::npos) << meta;
  EXPECT_NE(meta.find("\"bounds\":[6.5,45.75,7.25,46.5]"), std::string::npos) << meta;
}

TEST(Folder, ResumeDeletesTemporariesAndOverwriteSparesForeignFolders) {
  ScratchDir dir;
  const std::string out = dir.file("t");
  {
    auto a = open_archive(out);
    a->put({1, 0, 0}, as_bytes(std::string("a")));
  }  // destroyed without finish: a killed run
  const fs::path temp = dir.path() / "t/1/0/.1.png.tmp-Ab12Cd";  // as a kill mid-tile leaves it
  { std::ofstream(temp) << "half a tile"; }
  auto a = open_archive(out, {.mode = OpenMode::Resume});
  EXPECT_FALSE(fs::exists(temp));
  EXPECT_TRUE(a->has({1, 0, 0}));
  EXPECT_FALSE(a->has({1, 0, 1}));
  a->put({1, 0, 1}, as_bytes(std::string("b")));
  a->finish(sample_metadata());
  EXPECT_EQ(read_content(out), (Content{{{1, 0, 0}, "a"}, {{1, 0, 1}, "b"}}));

  fs::create_directories(dir.path() / "home");
  { std::ofstream(dir.path() / "home/notes.txt") << "keep me"; }
  EXPECT_THROW(open_archive(dir.file("home"), {.mode = OpenMode::Overwrite}), TileArchiveError);
  EXPECT_TRUE(fs::exists(dir.path() / "home/notes.txt"));
}

TEST(MBTiles, SchemaRowsAndMetadataThroughTheSqliteCli) {
  ScratchDir dir;
  const std::string out = dir.file("t.mbtiles");
  write_archive(out, {{{3, 2, 1}, "z3"}, {{0, 0, 0}, "z0"}});
  const auto q = [&](const std::string& sql) { return shell("sqlite3 '" + out + "' \"" + sql + "\""); };
  // TMS rows: y=1 at z3 is row 2^3 − 1 − 1 = 6.
  EXPECT_EQ(q("SELECT zoom_level, tile_column, tile_row, CAST(tile_data AS TEXT) FROM tiles ORDER BY 1"),
            "0|0|0|z0\n3|2|6|z3\n");
  EXPECT_EQ(q("SELECT typeof(tile_data) FROM tiles LIMIT 1"), "blob\n");
  EXPECT_EQ(q("SELECT name, value FROM metadata ORDER BY name"),
            "attribution|skylit\nbounds|6.5,45.75,7.25,46.5\ncenter|6.875,46.125,3\n"
            "description|hillshade\nformat|png\nmaxzoom|3\nminzoom|0\nname|skylit test\ntype|overlay\n");
  EXPECT_EQ(q("SELECT sql FROM sqlite_master WHERE name = 'tiles'"),
            "CREATE TABLE tiles (zoom_level integer, tile_column integer, tile_row integer,\n"
            "                                  tile_data blob)\n");
  // The unique index on (zoom_level, tile_column, tile_row).
  EXPECT_EQ(q("SELECT \\\"unique\\\" FROM pragma_index_list('tiles')"), "1\n");
  EXPECT_EQ(q("SELECT name FROM pragma_index_info('tile_index') ORDER BY seqno"),
            "zoom_level\ntile_column\ntile_row\n");
  EXPECT_EQ(q("PRAGMA application_id"), "1297105496\n");  // 0x4d504258
  EXPECT_EQ(q("PRAGMA integrity_check"), "ok\n");
  // A tile written by another tool (row flipped by hand) reads back at its XYZ address.
  q("INSERT INTO tiles VALUES (2, 1, 0, CAST('south' AS BLOB))");
  EXPECT_EQ(open_reader(out)->get({2, 1, 3}), "south");
}

TEST(PMTiles, HeaderReadByOffset) {
  ScratchDir dir;
  const std::string out = dir.file("t.pmtiles");
  const Content c = pyramid(0, 3);
  write_archive(out, c);
  const std::string b = file_bytes(out);
  ASSERT_GE(b.size(), 127u);
  EXPECT_EQ(b.substr(0, 7), "PMTiles");
  EXPECT_EQ(b[7], 3);
  const auto root_off = le(b, 0x08, 8), root_len = le(b, 0x10, 8);
  EXPECT_EQ(root_off, 127u);
  EXPECT_LE(root_off + root_len, 16384u);
  EXPECT_EQ(le(b, 0x18, 8), root_off + root_len);  // metadata right after the root
  EXPECT_EQ(le(b, 0x30, 8), 0u);                   // no leaves for 85 tiles
  const auto data_off = le(b, 0x38, 8), data_len = le(b, 0x40, 8);
  EXPECT_EQ(data_off + data_len, b.size());
  std::uint64_t sum = 0;
  for (const auto& [t, bytes] : c) sum += bytes.size();
  EXPECT_EQ(data_len, sum);            // all distinct: each stored once
  EXPECT_EQ(le(b, 0x48, 8), c.size());  // addressed tiles
  EXPECT_EQ(le(b, 0x58, 8), c.size());  // contents
  EXPECT_EQ(b[0x60], 1);                // clustered
  EXPECT_EQ(b[0x61], 2);                // gzip directories
  EXPECT_EQ(b[0x62], 1);                // tiles uncompressed
  EXPECT_EQ(b[0x63], 2);                // png
  EXPECT_EQ(b[0x64], 0);
  EXPECT_EQ(b[0x65], 3);
  EXPECT_EQ(static_cast<std::int32_t>(le(b, 0x66, 4)), 65000000);   // west 6.5
  EXPECT_EQ(static_cast<std::int32_t>(le(b, 0x6a, 4)), 457500000);  // south 45.75
  EXPECT_EQ(static_cast<std::int32_t>(le(b, 0x6e, 4)), 72500000);   // east 7.25
  EXPECT_EQ(static_cast<std::int32_t>(le(b, 0x72, 4)), 465000000);  // north 46.5
  EXPECT_EQ(b[0x76], 3);
  EXPECT_EQ(static_cast<std::int32_t>(le(b, 0x77, 4)), 68750000);
  EXPECT_EQ(static_cast<std::int32_t>(le(b, 0x7b, 4)), 461250000);
  // Metadata: gzip JSON, checked with the gzip CLI.
  { std::ofstream(dir.path() / "m.gz", std::ios::binary) << b.substr(le(b, 0x18, 8), le(b, 0x20, 8)); }
  const std::string json = shell("gzip -dc '" + (dir.path() / "m.gz").string() + "'");
  EXPECT_NE(json.find("\"name\":\"skylit test\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"format\":\"png\""), std::string::npos) << json;
  // Clustered: the first tile (id 0, z0) is at offset 0 of the data section.
  EXPECT_EQ(b.substr(data_off, payload({0, 0, 0}).size()), payload({0, 0, 0}));
}

TEST(PMTiles, IdenticalTilesAreStoredOnceAndRunsShareAnEntry) {
  ScratchDir dir;
  const std::string sea(3000, 's'), land(2000, 'l');
  Content c;
  // z3 in Hilbert order: ids 21..84; the first 40 sea (one run), then land and sea alternating.
  for (std::uint64_t id = 21; id < 85; ++id) {
    const TileId t = pmtiles::tile_of(id);
    c[t] = id < 61 || id % 2 == 0 ? sea : land;
  }
  const std::string out = dir.file("t.pmtiles");
  write_archive(out, c);
  const std::string b = file_bytes(out);
  EXPECT_EQ(le(b, 0x40, 8), sea.size() + land.size());  // two contents, once each
  EXPECT_EQ(le(b, 0x58, 8), 2u);
  EXPECT_EQ(le(b, 0x48, 8), 64u);       // addressed
  EXPECT_EQ(le(b, 0x50, 8), 1u + 24u);  // one entry for the run of 40, then 24 singles
  EXPECT_LT(b.size(), 6000u);
  EXPECT_EQ(read_content(out), c);
}

TEST(PMTiles, LeafDirectoriesAtRealSize) {
  ScratchDir dir;
  const std::string out = dir.file("t.pmtiles");
  Content c;
  for (int i = 0; i < 40000; ++i) {  // z8 has 65536 tiles; every 1.6th is put
    const TileId t{8, (i * 37) % 256, (i * 37) / 256 % 256};
    c[t] = payload(t, 1 + i % 97);
  }
  write_archive(out, c, {}, [] {
    auto m = sample_metadata();
    m.maxzoom = 8;
    return m;
  }());
  const std::string b = file_bytes(out);
  EXPECT_GT(le(b, 0x30, 8), 0u) << "no leaf directories";
  EXPECT_LE(le(b, 0x08, 8) + le(b, 0x10, 8), 16384u);
  const auto root = pmtiles::decode_directory(pmtiles::gunzip(b.substr(le(b, 0x08, 8), le(b, 0x10, 8))));
  for (const auto& e : root) EXPECT_EQ(e.run_length, 0u);
  EXPECT_EQ(read_content(out), c);
}

TEST(PMTiles, LeafDirectoriesWithASmallRootLimit) {
  ScratchDir dir;
  const std::string out = dir.file("t.pmtiles");
  const Content c = pyramid(0, 4);
  write_archive(out, c, {.pmtiles_max_root_bytes = 40});
  const std::string b = file_bytes(out);
  EXPECT_GT(le(b, 0x30, 8), 0u);
  EXPECT_LE(le(b, 0x10, 8), 40u);
  EXPECT_EQ(read_content(out), c);
}

}  // namespace
}  // namespace skylit::tiles
