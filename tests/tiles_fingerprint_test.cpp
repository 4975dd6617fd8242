// Run fingerprints (tiles/fingerprint.h): every kind records them from the moment it is
// opened, a resume with other options is refused in one line naming the difference and
// changes nothing (finished or interrupted archives), a resume with the same ones goes
// on, and merge refuses inputs made with different options.
#include <gtest/gtest.h>

#include <map>

#include "tiles/archive.h"
#include "tiles/fingerprint.h"
#include "tiles/merge.h"
#include "tiles/reader.h"
#include "tiles_test_util.h"

namespace skylit::tiles {
namespace {

using namespace testing;

const std::string kRunA = "skylit=0.1.0\nzoom=0-1\nproduct=hillshade\n";
const std::string kRunB = "skylit=0.1.0\nzoom=0-2\nproduct=hillshade\n";

// Every file under `dir` by relative path (the archive, its partial, hidden files).
std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) out[fs::relative(e.path(), dir).string()] = file_bytes(e.path());
  return out;
}

TileMetadata metadata_with(const std::string& fp) {
  TileMetadata m = sample_metadata();
  m.maxzoom = 1;
  m.fingerprint = fp;
  return m;
}

// The resume is refused with the zoom named, and nothing under `dir` changes.
void expect_refused(const std::string& out, const ScratchDir& dir) {
  const auto before = snapshot(dir.path());
  try {
    open_archive(out, {.mode = OpenMode::Resume, .fingerprint = kRunB});
    ADD_FAILURE() << "resume with other options was accepted";
  } catch (const TileArchiveError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("zoom: 0-1 in the archive, 0-2 in this run"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_EQ(e.option(), "overwrite");
  }
  EXPECT_TRUE(snapshot(dir.path()) == before) << "a refused resume changed files";
}

class Fingerprint : public ::testing::TestWithParam<const char*> {};

TEST_P(Fingerprint, FinishedArchiveRecordsItAndRefusesOtherOptions) {
  ScratchDir dir;
  const std::string out = dir.file(GetParam());
  write_archive(out, pyramid(0, 1), {.fingerprint = kRunA}, metadata_with(kRunA));
  EXPECT_EQ(open_reader(out)->metadata().fingerprint, kRunA);
  expect_refused(out, dir);
  // The same options resume: every tile is there.
  auto a = open_archive(out, {.mode = OpenMode::Resume, .fingerprint = kRunA});
  EXPECT_TRUE(a->has({1, 1, 1}));
  a->finish(metadata_with(kRunA));
  EXPECT_EQ(read_content(out), pyramid(0, 1));
}

TEST_P(Fingerprint, InterruptedArchiveRecordsItFromTheStart) {
  ScratchDir dir;
  const std::string out = dir.file(GetParam());
  {
    auto a = open_archive(out, {.batch_tiles = 1, .fingerprint = kRunA});
    a->put({0, 0, 0}, as_bytes(payload({0, 0, 0})));
  }  // no finish(): what an interrupted run leaves
  expect_refused(out, dir);
  auto a = open_archive(out, {.mode = OpenMode::Resume, .fingerprint = kRunA});
  EXPECT_TRUE(a->has({0, 0, 0}));
}

TEST_P(Fingerprint, AnArchiveWithoutOneIsNotResumedByARunThatRecordsOne) {
  ScratchDir dir;
  const std::string out = dir.file(GetParam());
  write_archive(out, pyramid(0, 1));
  const auto before = snapshot(dir.path());
  try {
    open_archive(out, {.mode = OpenMode::Resume, .fingerprint = kRunA});
    ADD_FAILURE() << "accepted";
  } catch (const TileArchiveError& e) {
    EXPECT_NE(std::string(e.what()).find("records no run options"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(snapshot(dir.path()) == before);
  // A caller that records none (fingerprint empty) resumes as before.
  EXPECT_TRUE(open_archive(out, {.mode = OpenMode::Resume})->has({0, 0, 0}));
}

INSTANTIATE_TEST_SUITE_P(Kinds, Fingerprint, ::testing::Values("out", "out.mbtiles", "out.pmtiles"),
                         [](const auto& info) { return std::string(archive_kind(info.param) == ArchiveKind::Folder
                                                                       ? "folder"
                                                                       : fs::path(info.param).extension().string().substr(1)); });

TEST(FingerprintMerge, InputsWithDifferentOptionsAreRefused) {
  ScratchDir dir;
  const Content c = pyramid(0, 1);
  Content first, second;
  for (const auto& [t, b] : c) (t.z == 0 ? first : second)[t] = b;
  write_archive(dir.file("a.pmtiles"), first, {.fingerprint = kRunA}, metadata_with(kRunA));
  write_archive(dir.file("b.mbtiles"), second, {.fingerprint = kRunB}, metadata_with(kRunB));
  write_archive(dir.file("c"), second, {.fingerprint = kRunA}, metadata_with(kRunA));
  try {
    merge({dir.file("a.pmtiles"), dir.file("b.mbtiles")}, dir.file("m.pmtiles"));
    ADD_FAILURE() << "merged";
  } catch (const TileArchiveError& e) {
    EXPECT_NE(std::string(e.what()).find("zoom: 0-1 in '"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir.file("m.pmtiles")));
  // Same options: merged, and the output records them.
  merge({dir.file("a.pmtiles"), dir.file("c")}, dir.file("m.pmtiles"));
  EXPECT_EQ(open_reader(dir.file("m.pmtiles"))->metadata().fingerprint, kRunA);
  EXPECT_EQ(read_content(dir.file("m.pmtiles")), c);
}

TEST(FingerprintText, DifferenceNamesTheFirstDifferingKey) {
  EXPECT_FALSE(fingerprint_difference(kRunA, kRunA));
  EXPECT_EQ(fingerprint_difference(kRunA, kRunB), "zoom: 0-1 in the archive, 0-2 in this run");
  EXPECT_EQ(fingerprint_difference("a=1\n", "a=1\nb=2\n"), "b: (none) in the archive, 2 in this run");
  EXPECT_EQ(fingerprint_difference("a=x=y\n", "a=x=z\n", "A", "B"), "a: x=y in A, x=z in B");  // first '=' splits
}

}  // namespace
}  // namespace skylit::tiles
