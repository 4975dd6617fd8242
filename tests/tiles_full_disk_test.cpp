// A full disk (a tiny tmpfs, ENOSPC) fails with one line and leaves the output as it
// was, the run resumable: after space is freed, a resumed run ends complete. Mounting
// needs root (CAP_SYS_ADMIN); elsewhere the tests skip, and fail where CI is set.
#include <gtest/gtest.h>

#include <cstdlib>

#include <random>

#include "tiles/archive.h"
#include "tiles_test_util.h"

namespace skylit::tiles {
namespace {

using namespace testing;

using terrain::testing::Tmpfs;

// Incompressible 4 KiB tiles: the tmpfs fills after a known handful.
Content noise_tiles(int z, std::size_t count) {
  Content c;
  std::mt19937 rng(5);
  for (int i = 0; i < static_cast<int>(count); ++i) {
    std::string s(4096, '\0');
    for (auto& ch : s) ch = static_cast<char>(rng());
    c[{z, i % (1 << z), i / (1 << z)}] = s;
  }
  return c;
}

TileMetadata metadata3() {
  auto m = sample_metadata();
  m.minzoom = m.maxzoom = 3;
  return m;
}

bool one_line(const std::string& s) { return !s.empty() && s.find('\n') == std::string::npos; }

void resume_to_the_end(const std::string& out, const Content& c) {
  auto a = open_archive(out, {.mode = OpenMode::Resume});
  for (const auto& [t, bytes] : c)
    if (!a->has(t)) a->put(t, as_bytes(bytes));
  a->finish(metadata3());
}

class FullDisk : public ::testing::TestWithParam<const char*> {
 protected:
  ScratchDir dir;
  Tmpfs fs_{dir.path() / "mnt", "64k"};
  std::string out = (dir.path() / "mnt" / GetParam()).string();
  bool is_file_kind() const { return archive_kind(out) != ArchiveKind::Folder; }

  void SetUp() override { SKYLIT_REQUIRE(fs_.mounted() ? "" : "cannot mount a tmpfs here (needs root)"); }
};

TEST_P(FullDisk, DuringPutsLeavesTheOldArchiveAndAResumableRun) {
  const Content c = noise_tiles(3, 64);  // 256 KiB of tiles on a 64 KiB disk
  const Content old{{{0, 0, 0}, "old"}};
  if (is_file_kind()) write_archive(out, old, {}, metadata3());
  const std::string before = is_file_kind() ? file_bytes(out) : std::string();
  std::string error;
  try {
    auto a = open_archive(out, {.mode = is_file_kind() ? OpenMode::Overwrite : OpenMode::Create,
                                .batch_tiles = 4});
    write_all(*a, c);
    a->finish(metadata3());
  } catch (const TileArchiveError& e) {
    error = e.what();
  }
  ASSERT_TRUE(one_line(error)) << "'" << error << "'";
  EXPECT_TRUE(error.find("No space left") != std::string::npos || error.find("full") != std::string::npos)
      << error;
  if (is_file_kind()) {
    EXPECT_EQ(file_bytes(out), before) << "the old archive changed";
    EXPECT_EQ(shell("sqlite3 '" + out + ".partial' 'PRAGMA integrity_check'"), "ok\n");
  } else {
    for (const auto& e : fs::recursive_directory_iterator(out)) {
      if (!e.is_regular_file()) continue;
      const std::string name = e.path().filename().string();
      EXPECT_FALSE(name.starts_with('.')) << "temporary left behind: " << e.path();
    }
  }
  ASSERT_TRUE(fs_.resize("8m"));
  resume_to_the_end(out, c);
  EXPECT_EQ(read_content(out), c);
}

INSTANTIATE_TEST_SUITE_P(Kinds, FullDisk, ::testing::Values("out", "out.mbtiles", "out.pmtiles"),
                         [](const auto& info) {
                           std::string s = info.param;
                           return s == "out" ? std::string("folder") : s.substr(4);
                         });

TEST(FullDiskPMTiles, DuringAssemblyKeepsTheOldArchiveAndTheStaging) {
  ScratchDir dir;
  Tmpfs tmp(dir.path() / "mnt", "200k");
  SKYLIT_REQUIRE(tmp.mounted() ? "" : "cannot mount a tmpfs here (needs root)");
  const std::string out = (dir.path() / "mnt/out.pmtiles").string();
  write_archive(out, {{{0, 0, 0}, "old"}}, {}, metadata3());
  const std::string before = file_bytes(out);
  const Content c = noise_tiles(3, 30);  // ~125 KiB staged fits; staged + assembled does not
  auto a = open_archive(out, {.mode = OpenMode::Overwrite});
  write_all(*a, c);
  try {
    a->finish(metadata3());
    FAIL() << "assembled " << fs::file_size(out) << " bytes on a full disk";
  } catch (const TileArchiveError& e) {
    EXPECT_TRUE(one_line(e.what())) << e.what();
    EXPECT_NE(std::string(e.what()).find("No space left"), std::string::npos) << e.what();
  }
  a.reset();
  EXPECT_EQ(file_bytes(out), before);
  EXPECT_FALSE(fs::exists(out + ".assembling"));
  ASSERT_TRUE(tmp.resize("8m"));
  resume_to_the_end(out, c);
  EXPECT_EQ(read_content(out), c);
}

}  // namespace
}  // namespace skylit::tiles
