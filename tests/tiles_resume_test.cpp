// A run killed with SIGKILL (a forked child) and then resumed ends with the same
// archive as an uninterrupted run: whole committed tiles only survive the kill, and
// the output path never holds an unfinished archive.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <random>
#include <thread>

#include "tiles/archive.h"
#include "tiles_test_util.h"

namespace skylit::tiles {
namespace {

using namespace testing;

constexpr int kBatch = 16;

// The tiles in a fixed shuffled order, as a sharded run would meet them.
std::vector<std::pair<TileId, std::string>> shuffled(const Content& c) {
  std::vector<std::pair<TileId, std::string>> v(c.begin(), c.end());
  std::shuffle(v.begin(), v.end(), std::mt19937(11));
  return v;
}

TileMetadata metadata4() {
  auto m = sample_metadata();
  m.maxzoom = 4;
  return m;
}

// Forks a child that puts `tiles` into `out` and is killed: by itself after `kill_after`
// puts, or (kill_after < 0) by the parent at a random moment after its first put.
void run_and_kill(const std::string& out, const std::vector<std::pair<TileId, std::string>>& tiles,
                  int kill_after, unsigned seed, bool* killed = nullptr) {
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    ::close(ready[0]);
    try {
      auto a = open_archive(out, {.mode = OpenMode::Resume, .batch_tiles = kBatch});
      for (int i = 0; i < static_cast<int>(tiles.size()); ++i) {
        if (i == kill_after) ::raise(SIGKILL);
        a->put(tiles[i].first, as_bytes(tiles[i].second));
        if (i == 0 && kill_after < 0 && ::write(ready[1], "x", 1) != 1) ::_exit(3);
      }
      a->finish(metadata4());
    } catch (...) {
      ::_exit(2);
    }
    ::_exit(0);
  }
  ::close(ready[1]);
  char c;
  if (kill_after < 0 && ::read(ready[0], &c, 1) == 1) {
    std::this_thread::sleep_for(std::chrono::microseconds(std::mt19937(seed)() % 40000));
    ::kill(pid, SIGKILL);
  }
  ::close(ready[0]);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  if (kill_after >= 0) {
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "status " << status;
  } else {
    ASSERT_TRUE(WIFSIGNALED(status) || (WIFEXITED(status) && WEXITSTATUS(status) == 0))
        << "status " << status;
  }
  if (killed) *killed = WIFSIGNALED(status);
}

int resume_to_the_end(const std::string& out, const std::vector<std::pair<TileId, std::string>>& tiles) {
  auto a = open_archive(out, {.mode = OpenMode::Resume, .batch_tiles = kBatch});
  int kept = 0;
  for (const auto& [t, bytes] : tiles) {
    if (a->has(t)) {
      ++kept;
      continue;
    }
    a->put(t, as_bytes(bytes));
  }
  a->finish(metadata4());
  return kept;
}

class KilledRun : public ::testing::TestWithParam<const char*> {
 protected:
  ScratchDir dir;
  std::string out = dir.file(GetParam());
  std::string reference = dir.file(std::string("ref_") + GetParam());
  Content content = pyramid(0, 4);  // 341 tiles
  std::vector<std::pair<TileId, std::string>> tiles = shuffled(content);

  void SetUp() override { write_archive(reference, content, {}, metadata4()); }
  bool is_file_kind() const { return archive_kind(out) != ArchiveKind::Folder; }

  void expect_same_as_reference() {
    EXPECT_EQ(read_content(out), content);
    EXPECT_EQ(open_reader(out)->metadata(), metadata4());
    if (archive_kind(out) == ArchiveKind::PMTiles) {
      EXPECT_EQ(file_bytes(out), file_bytes(reference));
    }
    if (archive_kind(out) == ArchiveKind::MBTiles) {
      EXPECT_EQ(shell("sqlite3 '" + out + "' 'SELECT * FROM metadata ORDER BY name'"),
                shell("sqlite3 '" + reference + "' 'SELECT * FROM metadata ORDER BY name'"));
    }
    EXPECT_FALSE(fs::exists(out + ".partial"));
  }
};

TEST_P(KilledRun, MidBatchKeepsWholeBatchesOnly) {
  run_and_kill(out, tiles, 37, 0);
  if (is_file_kind()) {
    EXPECT_FALSE(fs::exists(out)) << "an unfinished archive at the output path";
    const std::string partial = out + ".partial";
    EXPECT_EQ(shell("sqlite3 '" + partial + "' 'PRAGMA integrity_check'"), "ok\n");
    EXPECT_EQ(resume_to_the_end(out, tiles), 32);  // two committed batches of 16
  } else {
    EXPECT_EQ(resume_to_the_end(out, tiles), 37);  // each tile renamed into place whole
  }
  expect_same_as_reference();
}

TEST_P(KilledRun, AtRandomMomentsThenResumed) {
  int kills = 0;
  for (unsigned seed = 1; seed <= 4; ++seed) {
    bool killed = false;
    run_and_kill(out, tiles, -1, seed, &killed);
    kills += killed;
    if (is_file_kind() && fs::exists(out + ".partial")) {
      EXPECT_EQ(shell("sqlite3 '" + out + ".partial' 'PRAGMA integrity_check'"), "ok\n");
    }
  }
  EXPECT_GE(kills, 1) << "every child finished before its kill: the test tested nothing";
  resume_to_the_end(out, tiles);
  expect_same_as_reference();
}

TEST_P(KilledRun, ResumingAFinishedArchiveThenKilledKeepsIt) {
  const Content first = pyramid(0, 3);
  write_archive(out, first, {}, metadata4());
  const std::string before = is_file_kind() ? file_bytes(out) : std::string();
  run_and_kill(out, tiles, 100, 0);
  if (is_file_kind()) {
    EXPECT_EQ(file_bytes(out), before) << "the finished archive changed";
  }
  resume_to_the_end(out, tiles);
  expect_same_as_reference();
}

TEST_P(KilledRun, CreateRefusesAnInterruptedRunsLeftovers) {
  run_and_kill(out, tiles, 37, 0);
  try {
    open_archive(out);
    FAIL() << "created over an interrupted run";
  } catch (const TileArchiveError& e) {
    EXPECT_EQ(e.option(), is_file_kind() ? "resume" : "overwrite") << e.what();
  }
  auto a = open_archive(out, {.mode = OpenMode::Overwrite});
  EXPECT_FALSE(a->has(tiles[0].first));  // afresh
}

INSTANTIATE_TEST_SUITE_P(Kinds, KilledRun, ::testing::Values("out", "out.mbtiles", "out.pmtiles"),
                         [](const auto& info) {
                           std::string s = info.param;
                           return s == "out" ? std::string("folder") : s.substr(4);
                         });

TEST(PMTilesAssembly, ALeftoverAssemblyFileIsReplaced) {
  ScratchDir dir;
  const std::string out = dir.file("t.pmtiles");
  { std::ofstream(out + ".assembling") << "a killed finish()"; }
  write_archive(out, pyramid(0, 2), {.mode = OpenMode::Resume});
  EXPECT_EQ(dir.listing(), std::vector<std::string>{"t.pmtiles"});
  EXPECT_EQ(read_content(out), pyramid(0, 2));
}

}  // namespace
}  // namespace skylit::tiles
