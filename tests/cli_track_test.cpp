// `skylit track`: the shipped sample flight as JSON (values decoded by hand from its
// B records and the generator's plan: 601 fixes at 1 s, 20 V fixes from 10:05:45,
// so one 21 s gap after 10:05:44), the text summary of every format, and one-line
// errors with exit code 1 for files that are not tracks.
#include "cli_test_util.h"
#include "terrain_test_util.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

using skylit::testing::count_lines;
using skylit::testing::run_skylit;
using namespace skylit::terrain::testing;

namespace {

const std::string kSample = std::string(SKYLIT_SOURCE_DIR) + "/data/tracks/sample_glider.igc";
const std::string kData = std::string(SKYLIT_SOURCE_DIR) + "/tests/data/tracks/";

void expect_one_line_error(const std::string& args, const std::string& needle) {
  const auto r = run_skylit("track " + args, true);
  EXPECT_EQ(r.status, 1) << args << "\n" << r.out;
  EXPECT_EQ(count_lines(r.out), 1) << r.out;
  EXPECT_EQ(r.out.rfind("skylit: error: ", 0), 0u) << r.out;
  EXPECT_NE(r.out.find(needle), std::string::npos) << "expected '" << needle << "' in: " << r.out;
}

TEST(CliTrack, SampleFlightAsJson) {
  const auto r = run_skylit("track " + kSample + " --json --altitude pressure");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["summary"]["tracks"], 1);
  EXPECT_EQ(j["summary"]["fixes"], 601);
  EXPECT_EQ(j["summary"]["invalid_fixes"], 20);
  EXPECT_EQ(j["summary"]["start"], "2026-06-21T10:00:00Z");
  EXPECT_EQ(j["summary"]["end"], "2026-06-21T10:10:00Z");
  EXPECT_EQ(j["summary"]["duration_s"], 600.0);
  const auto& t = j["tracks"][0];
  EXPECT_EQ(t["id"], "D-KSKY");
  EXPECT_EQ(t["format"], "igc");
  ASSERT_EQ(t["summary"]["gaps"].size(), 1u);
  EXPECT_EQ(t["summary"]["gaps"][0]["start"], "2026-06-21T10:05:44Z");
  EXPECT_EQ(t["summary"]["gaps"][0]["length_s"], 21.0);
  const auto& f = t["fixes"][0];  // B100000 4654618N 00742786E A 02765 02800 009 07
  EXPECT_EQ(f["time"], "2026-06-21T10:00:00Z");
  EXPECT_NEAR(f["lat"].get<double>(), 46 + 54.618 / 60, 1e-12);
  EXPECT_NEAR(f["lon"].get<double>(), 7 + 42.786 / 60, 1e-12);
  EXPECT_EQ(f["valid"], true);
  EXPECT_EQ(f["pressure"]["m"], 2765.0);
  EXPECT_EQ(f["pressure"]["datum"], "pressure-isa");
  EXPECT_EQ(f["gnss"]["m"], 2800.0);
  EXPECT_EQ(f["gnss"]["datum"], "wgs84-ellipsoid");
  EXPECT_EQ(f["height_msl_m"], 2765.0);  // pressure altitude taken as MSL (ISA)
  EXPECT_EQ(f["extensions"]["FXA"], "009");
  EXPECT_EQ(f["extensions"]["SIU"], "07");
  const auto& v = t["fixes"][345];  // 10:05:45, the first V fix
  EXPECT_EQ(v["time"], "2026-06-21T10:05:45Z");
  EXPECT_EQ(v["valid"], false);
  EXPECT_FALSE(v.contains("gnss"));
  EXPECT_TRUE(v["height_msl_m"].is_null());
}

TEST(CliTrack, TextSummaryOfEveryFormat) {
  const auto igc = run_skylit("track " + kSample);
  ASSERT_EQ(igc.status, 0);
  EXPECT_NE(igc.out.find("601 fixes, 20 invalid, 1 gap over 15 s"), std::string::npos) << igc.out;
  EXPECT_NE(igc.out.find("gnss (wgs84-ellipsoid), pressure (pressure-isa)"), std::string::npos) << igc.out;
  const auto csv = run_skylit("track " + kData + "tiny_opensky.csv");
  ASSERT_EQ(csv.status, 0);
  EXPECT_NE(csv.out.find("2 tracks (csv)"), std::string::npos) << csv.out;
  EXPECT_NE(csv.out.find("3c6444 DLH4AB: 2026-06-21T10:00:00Z to 2026-06-21T10:00:10Z (10 s), 2 fixes"), std::string::npos) << csv.out;
  EXPECT_NE(run_skylit("track " + kData + "tiny.gpx").out.find("tiny gpx: 2026-06-21T10:00:00Z to 2026-06-21T10:00:02Z"), std::string::npos);
  EXPECT_NE(run_skylit("track " + kData + "tiny.kml").out.find("stated (egm96-msl)"), std::string::npos);
}

TEST(CliTrack, BadTracksEndInOneLine) {
  ScratchDir dir;
  expect_one_line_error(dir.file("missing.igc"), "cannot open");
  std::ofstream(dir.file("empty.igc")).flush();
  expect_one_line_error(dir.file("empty.igc"), "empty file");
  std::ofstream(dir.file("back.igc")) << "HFDTE210626\nB1000054812345N01101234EA0245002480\nB1000024812345N01101234EA0245002480\n";
  expect_one_line_error(dir.file("back.igc"), "back.igc:3: time 2026-06-21T10:00:02Z runs backwards");
  std::ofstream(dir.file("nodate.igc")) << "AXXX\nB1000054812345N01101234EA0245002480\n";
  expect_one_line_error(dir.file("nodate.igc"), "B record before any date header (HFDTE)");
  std::ofstream(dir.file("bin.csv"), std::ios::binary) << std::string("time\0\0\0\x01\x02", 9);
  expect_one_line_error(dir.file("bin.csv"), "binary content");
  expect_one_line_error(kSample + " --altitude sideways", "--altitude 'sideways' is not gnss, pressure or agl-offset=METRES");
  expect_one_line_error(kSample + " --altitude agl-offset=30", "reads no DEM");
  expect_one_line_error(kData + "tiny.gpx --altitude pressure", "has no altitude that --altitude pressure can use");
}

}  // namespace
