// `skylit shade --track FILE --aircraft SET --time T`: the aircraft of a track placed at
// the track's position at T casts its shadow where the sun projects it (the fix's
// position through PROJ/OGR, independently of the app's placement), and the inputs
// --track needs are refused with one line.
#include "cli_test_util.h"

#include <gtest/gtest.h>

#include <glm/vec2.hpp>
#include <ogr_spatialref.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <string>

using skylit::testing::expect_clean_shade_failure;
using skylit::testing::read_output;
using skylit::testing::run_skylit;
using namespace skylit::terrain::testing;

namespace {

constexpr double kLat = 46.9, kLon = 7.8;  // the fixes' place (UTM 32N)

glm::dvec2 utm32(double lat, double lon) {
  OGRSpatialReference wgs, utm;
  wgs.importFromEPSG(4326);
  utm.importFromEPSG(32632);
  wgs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  utm.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  std::unique_ptr<OGRCoordinateTransformation> t(OGRCreateCoordinateTransformation(&wgs, &utm));
  double x = lon, y = lat;
  t->Transform(1, &x, &y);
  return {x, y};
}

// "ddmmmmmN" / "dddmmmmmE" of an IGC B record.
std::string igc_lat(double v) {
  char b[16];
  const int d = static_cast<int>(v);
  std::snprintf(b, sizeof b, "%02d%05dN", d, static_cast<int>(std::lround((v - d) * 60000)));
  return b;
}
std::string igc_lon(double v) {
  char b[16];
  const int d = static_cast<int>(v);
  std::snprintf(b, sizeof b, "%03d%05dE", d, static_cast<int>(std::lround((v - d) * 60000)));
  return b;
}

// A 160 m × 120 m flat DEM at 100 m, 1 m texels, centred on the fixes' place.
std::string flat_dem(const ScratchDir& dir, glm::dvec2 centre) {
  RasterSpec s;
  s.width = 160;
  s.height = 120;
  s.values.assign(160 * 120, 100.0);
  s.epsg = 32632;
  s.gt = {std::round(centre.x) - 80.0, 1.0, 0, std::round(centre.y) + 60.0, 0, -1.0};
  return make_raster(dir.file("flat.tif"), s);
}

// Three fixes 1 s apart heading east at 30 m/s (0.000393° of longitude), GNSS height
// above the ellipsoid: placed with --track-altitude agl-offset=60 at 60 m above ground.
std::string igc(const ScratchDir& dir) {
  std::ofstream f(dir.file("t.igc"));
  f << "AXSK001\nHFDTEDATE:210626,01\n";
  for (int k = 0; k < 3; ++k)
    f << "B10000" << k << igc_lat(kLat) << igc_lon(kLon + (k - 1) * 0.000393) << "A0100001000\n";
  return dir.file("t.igc");
}

TEST(CliTrackShade, TheAircraftsShadowFallsWhereTheSunProjectsIt) {
  ScratchDir dir;
  const glm::dvec2 c = utm32(kLat, kLon);
  const std::string dem = flat_dem(dir, c), track = igc(dir), out = dir.file("s.tif");
  // Texels in umbra (a penumbra 60 m·0.0093 = 0.6 m wide): at least half the planform, as
  // the airliner's wings alone are 34 m × 4 m, the glider's 15 m × 0.6 m or more.
  for (const auto& [aircraft, min_texels] : {std::pair{"airliner", 60}, std::pair{"glider", 5}}) {
    const auto r = run_skylit("shade " + dem + " -o " + out + " -p shadow --track " + track + " --aircraft " + aircraft +
                                  " --track-altitude agl-offset=60 --time 2026-06-21T10:00:01Z "
                                  "--sun-azimuth 180 --sun-elevation 60 -q --overwrite",
                              true);
    ASSERT_EQ(r.status, 0) << r.out;
    const auto v = read_output(out).v;
    const double x0 = std::round(c.x) - 80.0, y0 = std::round(c.y) + 60.0;
    double n = 0, sx = 0, sy = 0;
    for (int j = 0; j < 120; ++j)
      for (int i = 0; i < 160; ++i)
        if (v[j * 160 + i] < 0.5f) {
          ++n;
          sx += x0 + i + 0.5;
          sy += y0 - j - 0.5;
        }
    ASSERT_GE(n, min_texels) << aircraft << ": no shadow";
    // The sun due south at 60°: the shadow of a point 60 m up lies 60/tan 60° north of it.
    // The set's centroid is within a few metres of its reference point.
    EXPECT_NEAR(sx / n, c.x, 4.0) << aircraft;
    EXPECT_NEAR(sy / n, c.y + 60.0 / std::tan(M_PI / 3), 4.0) << aircraft;
  }
}

TEST(CliTrackShade, ATrackBesideTheDemIsANote) {
  ScratchDir dir;
  const glm::dvec2 c = utm32(kLat, kLon);
  const std::string track = igc(dir), out = dir.file("s.tif");
  // GNSS heights (an offset above the ground would need ground under the fixes).
  for (const double east : {0.0, 2000.0}) {  // the DEM under the fixes, then 2 km east of them
    const std::string dem = flat_dem(dir, c + glm::dvec2(east, 0.0));
    const auto r = run_skylit("shade " + dem + " -o " + out + " -p shadow --track " + track +
                                  " --time 2026-06-21T10:00:01Z "
                                  "--sun-azimuth 180 --sun-elevation 60 --overwrite",
                              true);
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_EQ(r.out.find("note: --track: track 1 lies outside the DEM") != std::string::npos, east > 0.0) << r.out;
  }
}

TEST(CliTrackShade, BadInputsFailWithOneLine) {
  ScratchDir dir;
  const std::string dem = flat_dem(dir, utm32(kLat, kLon)), track = igc(dir);
  const std::string base = dem + " -o " + dir.file("x.tif") + " -p shadow --track " + track;
  expect_clean_shade_failure(dir, base, "--track needs --time");
  expect_clean_shade_failure(dir, base + " --time 2026-06-21T10:00:01Z --aircraft zeppelin", "--aircraft");
  expect_clean_shade_failure(dir, base + " --time 2026-06-21T10:00:01Z --track-altitude sideways", "--altitude");
  expect_clean_shade_failure(dir, "--synthetic -o " + dir.file("x.tif") + " -p shadow --track " + track +
                                      " --time 2026-06-21T10:00:01Z",
                             "needs a DEM with a CRS");
}

}  // namespace
