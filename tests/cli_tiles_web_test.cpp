// `skylit tiles -w leaflet` seen as a person sees it, and its PMTiles read by a reader
// that is not skylit's: tests/web/viewer_test.mjs opens the page in Debian's headless
// chromium (puppeteer-core) through a Range-capable static server and compares the
// screenshot with the tiles the page shows; tests/web/read_pmtiles.mjs reads the
// archive with npm's `pmtiles` (protomaps' reader), whose tiles must be the bytes of the
// same run written as a folder. Needs node, chromium and `npm ci --prefix tests/web`
// (scripts/test.sh runs it): skipped without them, failed where CI is set.
#include "cli_test_util.h"
#include "terrain_test_util.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>

namespace skylit::testing {
namespace {

namespace fs = std::filesystem;
using terrain::testing::ScratchDir;
using terrain::testing::shared_dem;

const std::string kWeb = std::string(SKYLIT_SOURCE_DIR) + "/tests/web";

// What the tests need and lack ("": nothing).
std::string missing_web_tools() {
  if (std::system("command -v node >/dev/null 2>&1") != 0) return "node not on PATH";
  if (!fs::exists("/usr/bin/chromium") && !std::getenv("CHROMIUM")) return "no /usr/bin/chromium (or $CHROMIUM)";
  if (!fs::exists(kWeb + "/node_modules/puppeteer-core") || !fs::exists(kWeb + "/node_modules/pmtiles"))
    return "tests/web/node_modules missing: run npm ci --prefix tests/web";
  if (!fs::exists(shared_dem("big_tujunga_srtm30_utm11n.tif"))) return "../shared/dem is absent";
  return "";
}
#define REQUIRE_WEB() SKYLIT_REQUIRE(missing_web_tools())

// stdout of a shell command, and its exit status.
std::string capture(const std::string& cmd, int& status) {
  FILE* pipe = popen(cmd.c_str(), "r");
  std::string out;
  char buf[4096];
  std::size_t n;
  while (pipe && (n = std::fread(buf, 1, sizeof buf, pipe)) > 0) out.append(buf, n);
  const int raw = pipe ? pclose(pipe) : -1;
  status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return out;
}

// "z/x/y" → SHA-256 of every tile file of a folder archive, by coreutils' sha256sum.
std::map<std::string, std::string> folder_hashes(const fs::path& root) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(root)) {
    if (e.path().extension() != ".png") continue;
    int status = 0;
    const std::string line = capture("sha256sum '" + e.path().string() + "'", status);
    const fs::path rel = fs::relative(e.path(), root);
    const std::string key = rel.parent_path().string() + "/" + rel.stem().string();
    out[key] = line.substr(0, line.find(' '));
  }
  return out;
}

class TilesWeb : public ::testing::Test {
 protected:
  void SetUp() override {
    crop_ = dir_.file("crop.tif");
    ASSERT_EQ(std::system(("gdal_translate -q -srcwin 400 200 300 250 " + shared_dem("big_tujunga_srtm30_utm11n.tif") +
                           " " + crop_)
                              .c_str()),
              0);
  }
  ScratchDir dir_;
  std::string crop_;
  const std::string flags_ = " --zoom 10-12 -p hillshade -q";
};

TEST_F(TilesWeb, NpmPmtilesReadsTheArchiveAsTheFolderRunWroteIt) {
  REQUIRE_WEB();
  auto r = run_skylit("tiles " + crop_ + " -o " + dir_.file("t.pmtiles") + flags_, true);
  ASSERT_EQ(r.status, 0) << r.out;
  r = run_skylit("tiles " + crop_ + " -o " + dir_.file("xyz") + flags_, true);
  ASSERT_EQ(r.status, 0) << r.out;
  int status = 0;
  const std::string text = capture("node " + kWeb + "/read_pmtiles.mjs " + dir_.file("t.pmtiles"), status);
  ASSERT_EQ(status, 0) << text;
  const nlohmann::json j = nlohmann::json::parse(text);
  EXPECT_EQ(j["header"]["specVersion"], 3);
  EXPECT_EQ(j["header"]["tileType"], 2);  // PNG
  EXPECT_EQ(j["header"]["clustered"], true);
  EXPECT_EQ(j["header"]["minZoom"], 10);
  EXPECT_EQ(j["header"]["maxZoom"], 12);
  EXPECT_EQ(j["metadata"]["format"], "png");
  std::map<std::string, std::string> from_reader;
  for (const auto& [key, hash] : j["tiles"].items()) from_reader[key] = hash;
  const auto from_folder = folder_hashes(dir_.file("xyz"));
  EXPECT_GE(from_folder.size(), 10u);
  EXPECT_EQ(from_reader, from_folder);
}

TEST_F(TilesWeb, LeafletPageShowsTheTilesInChromium) {
  REQUIRE_WEB();
  for (const std::string out : {"t.pmtiles", "xyz"}) {
    const auto r = run_skylit("tiles " + crop_ + " -o " + dir_.file(out) + flags_ + " -w leaflet", true);
    ASSERT_EQ(r.status, 0) << r.out;
    const std::string root = out == "xyz" ? dir_.file("xyz") : dir_.path().string();
    ASSERT_TRUE(fs::exists(root + "/index.html")) << out;
    int status = 0;
    const std::string shot = dir_.file(out + ".png");
    const std::string text = capture("node " + kWeb + "/viewer_test.mjs " + root + " index.html " + shot, status);
    EXPECT_EQ(status, 0) << out << ": " << text;
    ASSERT_FALSE(text.empty()) << out;
    const nlohmann::json j = nlohmann::json::parse(text);
    EXPECT_GE(j["tiles"].get<int>(), 4) << out;  // the crop spans six z12 tiles in a 768 × 512 view
    EXPECT_EQ(j["zoom"], 12) << out;             // opened at the deepest zoom, tiles at their own scale
    EXPECT_GT(j["compared"].get<int>(), 30000) << out;
    EXPECT_EQ(j["mismatched"], 0) << out;
    if (out == "t.pmtiles") {
      EXPECT_GT(j["range_requests"].get<int>(), 1);  // the reader reads by ranges
    }
    EXPECT_TRUE(fs::exists(shot));
  }
}

// A DEM across the antimeridian (the synthetic scene at 179.85° E … 179.85° W): the page
// frames it and shows the tiles of both sides, those past 180° read from the world's
// first columns, as the archive holds them.
TEST_F(TilesWeb, LeafletPageShowsBothSidesOfTheAntimeridian) {
  REQUIRE_WEB();
  const std::string scene = dir_.file("scene.tif"), dem = dir_.file("dateline.tif");
  ASSERT_EQ(run_skylit("scene --size 256 -o " + scene).status, 0);
  ASSERT_EQ(std::system(("gdal_translate -q -a_srs EPSG:4326 -a_ullr 179.85 -17.8 180.15 -18.1 " + scene + " " + dem).c_str()), 0);
  for (const std::string out : {"d.pmtiles", "dxyz"}) {
    const auto r = run_skylit("tiles " + dem + " -o " + dir_.file(out) + " --zoom 10-11 -p hillshade -q -w leaflet", true);
    ASSERT_EQ(r.status, 0) << r.out;
    const std::string root = out == "dxyz" ? dir_.file("dxyz") : dir_.path().string();
    int status = 0;
    const std::string text = capture("node " + kWeb + "/viewer_test.mjs " + root + " index.html " + dir_.file(out + ".png"), status);
    EXPECT_EQ(status, 0) << out << ": " << text;
    ASSERT_FALSE(text.empty()) << out;
    const nlohmann::json j = nlohmann::json::parse(text);
    EXPECT_EQ(j["zoom"], 11) << out;
    EXPECT_EQ(j["mismatched"], 0) << out;
    int west = 0, east = 0;  // Leaflet's columns: 2047 left of 180°, 2048 (the archive's 0) right of it
    for (const auto& key : j["keys"]) {
      const std::string k = key.get<std::string>();
      west += k.rfind("11/2047/", 0) == 0;
      east += k.rfind("11/2048/", 0) == 0;
    }
    EXPECT_GE(west, 1) << out << ": " << text;
    EXPECT_GE(east, 1) << out << ": " << text;
  }
}

TEST_F(TilesWeb, LeafletWithMbtilesFailsCleanly) {
  const auto before = dir_.listing();
  const auto r = run_skylit("tiles " + crop_ + " -o " + dir_.file("t.mbtiles") + flags_ + " -w leaflet", true);
  EXPECT_EQ(r.status == 1 || r.status == 2, true) << r.out;
  EXPECT_EQ(count_lines(r.out), 1) << r.out;
  EXPECT_NE(r.out.find("cannot read MBTiles"), std::string::npos) << r.out;
  EXPECT_EQ(dir_.listing(), before);
}

}  // namespace
}  // namespace skylit::testing
