// `skylit track FILE --dem DEM`: the sample glider over `skylit scene`'s DEM. Every
// placed fix gets a finite, consistent terrain object: its ground checked against the
// DEM read here and the fix projected by OGR, its sun against `skylit sun`; at the
// glider's 2600–2900 m over terrain below 2200 m the sky is open, and flown 5 m above
// the ground it is not. Bad DEMs and a track off the DEM end in one line.
#include "cli_test_util.h"
#include "terrain_test_util.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <memory>
#include <string>

using skylit::testing::count_lines;
using skylit::testing::read_output;
using skylit::testing::run_skylit;
using namespace skylit::terrain::testing;
using nlohmann::json;

namespace {

const std::string kSample = std::string(SKYLIT_SOURCE_DIR) + "/data/tracks/sample_glider.igc";

// One scene DEM for the whole suite (0.2 s to write, but eight runs read it).
class CliTrackTerrain : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new ScratchDir;
    ASSERT_EQ(run_skylit("scene -o " + dir_->file("scene.tif") + " -q").status, 0);
  }
  static void TearDownTestSuite() { delete dir_; }
  static std::string scene() { return dir_->file("scene.tif"); }
  static json track_json(const std::string& args) {
    const auto r = run_skylit("track " + kSample + " --dem " + scene() + " --json " + args);
    EXPECT_EQ(r.status, 0) << r.out;
    return json::parse(r.out);
  }
  static ScratchDir* dir_;
};
ScratchDir* CliTrackTerrain::dir_ = nullptr;

// Fractional texel (column, row) of a place, projected through OGR (not the app's code).
std::pair<double, double> texel_of(const skylit::testing::OutputRaster& dem, double lat, double lon) {
  OGRSpatialReference wgs, utm;
  wgs.importFromEPSG(4326);
  utm.importFromEPSG(32632);
  wgs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  utm.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  std::unique_ptr<OGRCoordinateTransformation> t(OGRCreateCoordinateTransformation(&wgs, &utm));
  double x = lon, y = lat;
  t->Transform(1, &x, &y);
  return {(x - dem.gt[0]) / dem.gt[1] - 0.5, (y - dem.gt[3]) / dem.gt[5] - 0.5};
}

// Sampled bilinearly from the file.
double ground_under(const skylit::testing::OutputRaster& dem, double lat, double lon) {
  const auto [u, v] = texel_of(dem, lat, lon);
  const int i = static_cast<int>(u), j = static_cast<int>(v);
  const double a = u - i, b = v - j;
  return (1 - b) * ((1 - a) * dem.at(0, i, j) + a * dem.at(0, i + 1, j)) +
         b * ((1 - a) * dem.at(0, i, j + 1) + a * dem.at(0, i + 1, j + 1));
}

// How far (m, horizontally) a shipped set's r³-weighted centroid, where the terrain is
// marched from, lies from its reference point: read from data/aircraft/ here.
double centroid_offset_m(const std::string& set) {
  std::ifstream in(std::string(SKYLIT_SOURCE_DIR) + "/data/aircraft/" + set + ".json");
  const json j = json::parse(in);
  double w = 0.0, x = 0.0, y = 0.0;
  for (const json& s : j["spheres"]) {
    const double r3 = std::pow(s["radius"].get<double>(), 3);
    w += r3, x += r3 * s["centre"][0].get<double>(), y += r3 * s["centre"][1].get<double>();
  }
  return std::hypot(x / w, y / w);
}

// The steepest slope (rise over run) between neighbouring texels within `radius_m` (and
// a texel) of a place: how much the ground can change over that distance from it.
double local_max_slope(const skylit::testing::OutputRaster& dem, double lat, double lon, double radius_m) {
  const auto [u, v] = texel_of(dem, lat, lon);
  const int reach = static_cast<int>(std::ceil(radius_m / std::abs(dem.gt[1]))) + 1;
  double m = 0.0;
  for (int j = std::max(0, static_cast<int>(v) - reach); j <= std::min(dem.h - 2, static_cast<int>(v) + reach + 1); ++j)
    for (int i = std::max(0, static_cast<int>(u) - reach); i <= std::min(dem.w - 2, static_cast<int>(u) + reach + 1); ++i)
      m = std::max({m, std::abs(dem.at(0, i + 1, j) - dem.at(0, i, j)) / std::abs(dem.gt[1]),
                    std::abs(dem.at(0, i, j + 1) - dem.at(0, i, j)) / std::abs(dem.gt[5])});
  return m;
}

// Every field finite and in range, and the sun's fields consistent with one another.
void expect_consistent(const json& t) {
  for (const char* key : {"ground_m", "height_above_ground_m", "sun_azimuth_deg", "sun_elevation_deg",
                          "sun_horizon_deg", "sun_visible_fraction", "sky_view", "sky_fraction"})
    ASSERT_TRUE(t[key].is_number() && std::isfinite(t[key].get<double>())) << key << " " << t;
  const double sky = t["sky_view"], frac = t["sky_fraction"], sun = t["sun_visible_fraction"];
  EXPECT_TRUE(sky >= 0 && sky <= 1 + 1e-12 && frac >= 0 && frac <= 1 + 1e-12 && sun >= 0 && sun <= 1) << t;
  EXPECT_GE(sky, frac - 1e-12) << t;  // cos²σ ≥ 1 − sin σ for σ ∈ [0, π/2]
  const double margin = t["sun_elevation_deg"].get<double>() - t["sun_horizon_deg"].get<double>();
  EXPECT_EQ(t["in_terrain_shadow"].get<bool>(), margin < 0) << t;
  if (margin > 0.27) {  // the disc's radius is 0.267°
    EXPECT_EQ(sun, 1.0) << t;
  }
  if (margin < -0.27) {
    EXPECT_EQ(sun, 0.0) << t;
  }
  EXPECT_TRUE(t["inside_dem"].get<bool>());
  EXPECT_FALSE(t["below_ground"].get<bool>());
}

TEST_F(CliTrackTerrain, GliderAltitudeSeesOpenSky) {
  const json j = track_json("");
  const auto dem = read_output(scene());
  ASSERT_GT(dem.w, 0);
  const json& track = j["tracks"][0];
  const double offset = centroid_offset_m("glider");
  int placed = 0;
  for (const json& f : track["fixes"]) {
    if (!f["valid"].get<bool>()) {
      EXPECT_TRUE(f["terrain"].is_null()) << f;
      continue;
    }
    const json& t = f["terrain"];
    ASSERT_TRUE(t.is_object()) << f;
    ++placed;
    expect_consistent(t);
    // The glider's centroid is centroid_offset_m from its reference point horizontally:
    // the ground under it differs by at most that times the steepest slope.
    const double slack = offset * local_max_slope(dem, f["lat"], f["lon"], offset);
    EXPECT_NEAR(t["ground_m"].get<double>(), ground_under(dem, f["lat"], f["lon"]), 0.5 + slack) << f;
    // 2600–2900 m over terrain below 2200 m: every horizon below the horizontal.
    EXPECT_GT(t["height_above_ground_m"].get<double>(), 300.0) << f;
    EXPECT_NEAR(t["sky_view"].get<double>(), 1.0, 1e-12) << f;
    EXPECT_FALSE(t["in_terrain_shadow"].get<bool>()) << f;
    EXPECT_EQ(t["sun_visible_fraction"].get<double>(), 1.0) << f;
  }
  EXPECT_EQ(placed, 581);
  const json& s = track["summary"]["terrain"];
  EXPECT_EQ(s["aircraft"], "glider");
  EXPECT_EQ(s["fixes"], 581);
  EXPECT_EQ(s["fixes_over_dem"], 581);
  EXPECT_EQ(s["in_terrain_shadow"], 0);
  EXPECT_NEAR(s["sky_view_min"].get<double>(), 1.0, 1e-12);

  // The sun of the first fix, as `skylit sun` gives it for that place and time.
  const json& f = track["fixes"][0];
  const auto sun = run_skylit("sun --lat " + f["lat"].dump() + " --lon " + f["lon"].dump() + " --time " +
                              f["time"].get<std::string>() + " --json");
  ASSERT_EQ(sun.status, 0) << sun.out;
  const json js = json::parse(sun.out);
  EXPECT_NEAR(f["terrain"]["sun_azimuth_deg"].get<double>(), js["azimuth_deg"].get<double>(), 1e-5);
  EXPECT_NEAR(f["terrain"]["sun_elevation_deg"].get<double>(), js["apparent_elevation_deg"].get<double>(), 1e-5);
}

TEST_F(CliTrackTerrain, FlownLowTheTerrainClosesTheSky) {
  const json j = track_json("--altitude agl-offset=5 --aircraft airliner");
  const json& track = j["tracks"][0];
  const double offset = centroid_offset_m("airliner");
  const auto dem = read_output(scene());
  double sum = 0.0;
  int n = 0, closed = 0;
  for (const json& f : track["fixes"]) {
    if (f["terrain"].is_null()) continue;
    const json& t = f["terrain"];
    expect_consistent(t);
    // The reference point is 5 m up (height_msl_m); the airliner's centroid lies
    // centroid_offset_m behind it, turned by the pitch of a path that follows the
    // slopes: the ground under it, and the pitch's lift of it, each differ by at most
    // that times the steepest slope near the fix.
    const double slack = offset * local_max_slope(dem, f["lat"], f["lon"], offset);
    EXPECT_NEAR(t["height_above_ground_m"].get<double>(), 5.0, 0.5 + 2.0 * slack) << f;
    EXPECT_NEAR(f["height_msl_m"].get<double>() - 5.0, t["ground_m"].get<double>(), 0.5 + slack) << f;
    sum += t["sky_view"].get<double>(), ++n;
    closed += t["sky_view"].get<double>() < 0.99;
  }
  ASSERT_EQ(n, 581);
  // Valley sides and ridges close part of the sky almost everywhere (measured: mean 0.85, min 0.68).
  EXPECT_GT(closed, n / 2);
  const json& s = track["summary"]["terrain"];
  EXPECT_NEAR(s["sky_view_mean"].get<double>(), sum / n, 1e-9);
  EXPECT_LT(s["sky_view_min"].get<double>(), s["sky_view_mean"].get<double>());
  EXPECT_EQ(s["aircraft"], "airliner");
}

TEST_F(CliTrackTerrain, TextModeAddsOneSummaryLineAndNoDemChangesNothing) {
  const auto r = run_skylit("track " + kSample + " --dem " + scene() + " --altitude agl-offset=5");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto plain = run_skylit("track " + kSample + " --altitude gnss");
  EXPECT_EQ(count_lines(r.out), count_lines(plain.out) + 1) << r.out;
  EXPECT_NE(r.out.find("  terrain (" + scene() + ", glider): 581 of 581 fixes over the DEM, "), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("% in terrain shadow, sky view min 0."), std::string::npos) << r.out;
  EXPECT_EQ(run_skylit("track " + kSample + " --json").out.find("terrain"), std::string::npos);
}

void expect_one_line_error(const std::string& args, const std::string& needle) {
  const auto r = run_skylit("track " + kSample + " " + args, true);
  EXPECT_EQ(r.status, 1) << args << "\n" << r.out;
  EXPECT_EQ(count_lines(r.out), 1) << r.out;
  EXPECT_EQ(r.out.rfind("skylit: error: ", 0), 0u) << r.out;
  EXPECT_NE(r.out.find(needle), std::string::npos) << "expected '" << needle << "' in: " << r.out;
}

TEST_F(CliTrackTerrain, BadDemsAndATrackOffTheDemEndInOneLine) {
  ScratchDir dir;
  expect_one_line_error("--dem " + dir.file("missing.tif"), "does not exist");
  expect_one_line_error("--dem " + make_crs_less_ramp(dir.file("nocrs.tif")), "has no CRS");
  // A flat DEM of the same CRS 100 km east of the scene.
  RasterSpec far;
  far.width = far.height = 64;
  far.epsg = 32632;
  far.gt = {515000, 30, 0, 5200000, 0, -30};
  expect_one_line_error("--dem " + make_raster(dir.file("far.tif"), far), "lies entirely outside --dem");
  expect_one_line_error("--dem " + scene() + " --aircraft zeppelin", "--aircraft");
}

}  // namespace
