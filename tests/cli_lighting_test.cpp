// `skylit shade` with a sun and a sky: --time (place from the DEM's CRS or --lat/--lon),
// --sun-azimuth/--sun-elevation and gdaldem's -az/-alt, --sky, the shadow and
// irradiance products, colour output, and bad lighting input rejected with one line,
// a non-zero exit and no output file.
#include "cli_test_util.h"
#include "terrain_test_util.h"

#include "shading/products.h"
#include "shading/sky/atmosphere.h"
#include "shading/sky/sun_disc.h"
#include "shading/sky/sun_position.h"
#include "terrain/geolocation.h"

#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <vector>

using Raster = skylit::testing::OutputRaster;
using skylit::testing::count_lines;
using skylit::testing::read_output;
using skylit::testing::run_skylit;
using skylit::testing::expect_clean_shade_failure;
using namespace skylit::terrain::testing;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// A north–south wall 100 m high on flat ground, 61×61 pixels of 10 m, UTM 11N (near
// Los Angeles): columns 5..7, rows 5..55. Heights are bilinear between texel centres,
// so the east face's top is column 7's centre (horizon_scenes.h, test::wall).
std::string make_wall(const ScratchDir& dir) {
  RasterSpec s;
  s.width = s.height = 61;
  s.gt = {380000, 10, 0, 3790000, 0, -10};
  s.values.assign(61 * 61, 0.0);
  for (int j = 5; j <= 55; ++j)
    for (int i = 5; i < 8; ++i) s.values[j * 61 + i] = 100.0;
  return make_raster(dir.file("wall.tif"), s);
}

// A Radiance RGBE image (flat scan lines: widths < 8 are never run-length encoded).
std::string make_hdr(const ScratchDir& dir, const std::string& name, int w, int h) {
  std::ofstream f(dir.file(name), std::ios::binary);
  f << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " << h << " +X " << w << "\n";
  for (int k = 0; k < w * h; ++k) f << '\x80' << '\x80' << '\x80' << '\x81';  // (1, 1, 1)
  return dir.file(name);
}

}  // namespace

TEST(CliLighting, BadLightingFailsCleanlyBeforeAnyWork) {
  ScratchDir dir;
  const std::string wall = make_wall(dir);
  const std::string out = wall + " -o " + dir.file("out.tif") + " -p irradiance --azimuths 4";
  expect_clean_shade_failure(dir, out + " --time yesterday", "invalid time");
  expect_clean_shade_failure(dir, out + " --time 2026-06-21T09:30:00", "zone");
  expect_clean_shade_failure(dir, out + " --time 2026-06-21T09:30:00Z --lat 95 --lon 0", "--lat: latitude 95");
  expect_clean_shade_failure(dir, out + " --sky hosek", "--sky: unknown sky 'hosek'");
  expect_clean_shade_failure(dir, out + " --sky cie:17", "1..16");
  expect_clean_shade_failure(dir, out + " --sky cie:0", "1..16");
  expect_clean_shade_failure(dir, out + " --turbidity 40", "--turbidity");
  expect_clean_shade_failure(dir, out + " --sun-elevation 120", "--sun-elevation");
  expect_clean_shade_failure(dir, out + " --sky " + dir.file("missing.hdr"), "missing.hdr");
  {
    std::ofstream(dir.file("garbage.hdr")) << "not an image\n";
  }
  expect_clean_shade_failure(dir, out + " --sky " + dir.file("garbage.hdr"), "garbage.hdr");
  expect_clean_shade_failure(dir, out + " --sky " + make_hdr(dir, "square.hdr", 3, 3), "width = 2 × height");
  // --time needs a place: a DEM without a CRS, and no --lat/--lon.
  RasterSpec no_crs;
  no_crs.width = no_crs.height = 8;
  no_crs.epsg.reset();
  no_crs.set_geotransform = false;
  const std::string nocrs = make_raster(dir.file("nocrs.tif"), no_crs);
  expect_clean_shade_failure(dir, nocrs + " -s 10 -o " + dir.file("o.tif") + " -p shadow --time 2026-06-21T09:30:00Z",
                       "--lat, --lon: a time needs the DEM's location");
  // The GPU has no exact sun march: an explicit --backend gpu refuses, in one line.
  expect_clean_shade_failure(dir, out + " --exact --backend gpu", "--backend gpu");
}

TEST(CliLighting, NoCrsWorksWithLatLonAndMapSkiesLoad) {
  ScratchDir dir;
  const std::string in = make_crs_less_ramp(dir.file("nocrs.tif"));
  const auto r = run_skylit("shade " + in + " -s 10 -o " + dir.file("e.tif") +
                                " -p irradiance --azimuths 4 -q --time 2026-06-21T12:00:00+02:00 --lat 46 --lon 8",
                            true);
  EXPECT_EQ(r.status, 0) << r.out;
  // A 2:1 map of radiance 1 (× --sky-scale 2): sky-only irradiance 2π on open ground.
  const std::string flat = make_raster(dir.file("flat.tif"), RasterSpec{});
  const auto m = run_skylit("shade " + flat + " -o " + dir.file("m.tif") + " -p irradiance --azimuths 8 -q --sky " +
                                make_hdr(dir, "sky.hdr", 4, 2) + " --sky-scale 2",
                            true);
  ASSERT_EQ(m.status, 0) << m.out;
  EXPECT_NEAR(read_output(dir.file("m.tif")).at(0, 1, 1), 2 * std::numbers::pi, 0.03 * 2 * std::numbers::pi);
}

TEST(CliLighting, ShadowProductBehindAWallWithGdaldemAngles) {
  ScratchDir dir;
  const std::string wall = make_wall(dir);
  // Receiver at column 47 sees the face top 400 m west at atan(100/400).
  const int i = 47, c = 30;
  const double sigma = std::atan(100.0 / ((i - 7) * 10.0));
  const double e = sigma + 0.4 * skylit::sky::kSunAngularRadius;
  char angles[64];
  std::snprintf(angles, sizeof angles, " -az 270 -alt %.9f", e / kDeg);
  const std::string out = dir.file("shadow.tif");
  const auto r = run_skylit("shade " + wall + " -o " + out + " -p shadow --exact --no-curvature -q" + angles, true);
  ASSERT_EQ(r.status, 0) << r.out;
  const Raster s = read_output(out);
  ASSERT_EQ(s.bands, 1);
  EXPECT_NEAR(s.at(0, i, c), skylit::sky::sun_disc_fraction(e, sigma, 0.0), 2e-3);
  EXPECT_EQ(s.at(0, 30, 2), 1.0f);  // north of the wall's end: open
  EXPECT_EQ(s.at(0, 12, c), 0.0f);  // close behind it: full shadow
  // The long spellings are the same option.
  const auto l = run_skylit("shade " + wall + " -o " + dir.file("l.tif") +
                                " -p shadow --exact --no-curvature -q --sun-azimuth 270 --sun-elevation " +
                                std::to_string(e / kDeg),
                            true);
  ASSERT_EQ(l.status, 0) << l.out;
  EXPECT_NEAR(read_output(dir.file("l.tif")).at(0, i, c), s.at(0, i, c), 1e-3);
}

TEST(CliLighting, TimeUsesTheDemsCentreAndShadowsMoveWithTheSun) {
  ScratchDir dir;
  const std::string wall = make_wall(dir);
  // Independent: the centre through GDAL, the sun through SPA.
  GDALDataset* ds = GDALDataset::Open(wall.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY);
  skylit::terrain::GeoReference g;
  ds->GetGeoTransform(g.geotransform.data());
  char* wkt = nullptr;
  ds->GetSpatialRef()->exportToWkt(&wkt);
  g.crs_wkt = wkt;
  CPLFree(wkt);
  GDALClose(GDALDataset::ToHandle(ds));
  const auto place = skylit::terrain::grid_centre_lat_lon(g, 61, 61);
  ASSERT_TRUE(place);
  EXPECT_NEAR(place->latitude_deg, 34.24, 0.02);  // UTM 11N (380 km E, 3790 km N): ~34.2°N 118.3°W
  EXPECT_NEAR(place->longitude_deg, -118.30, 0.02);

  // Late afternoon: the sun in the west-north-west puts the ground just east of the
  // wall in shadow; at noon it is lit. Irradiance of open ground falls with the sun.
  const std::string evening = dir.file("evening.tif"), noon = dir.file("noon.tif");
  const std::string args = " -p shadow --azimuths 8 -q --time ";
  ASSERT_EQ(run_skylit("shade " + wall + " -o " + evening + args + "2026-06-21T19:00:00-07:00").status, 0);
  ASSERT_EQ(run_skylit("shade " + wall + " -o " + noon + args + "2026-06-21T13:00:00-07:00").status, 0);
  const Raster ev = read_output(evening), nn = read_output(noon);
  EXPECT_EQ(ev.at(0, 10, 40), 0.0f);
  EXPECT_EQ(nn.at(0, 10, 40), 1.0f);
  EXPECT_LT(ev.mean(), nn.mean());

  const std::string e1 = dir.file("e1.tif"), e2 = dir.file("e2.tif");
  const std::string irr = " -p irradiance --azimuths 8 -q --sky preetham --time ";
  ASSERT_EQ(run_skylit("shade " + wall + " -o " + e1 + irr + "2026-06-21T13:00:00-07:00").status, 0);
  ASSERT_EQ(run_skylit("shade " + wall + " -o " + e2 + irr + "2026-06-21T19:00:00-07:00").status, 0);
  const auto sun = skylit::sky::solar_position(skylit::sky::parse_utc_time("2026-06-21T20:00:00Z"),
                                               {place->latitude_deg, place->longitude_deg, 0.0});
  const double el = sun.apparent_elevation_deg * kDeg;
  const double open = skylit::sky::esra_diffuse_horizontal(el, 3.0) + skylit::sky::broadband_dni(el, 3.0) * std::sin(el);
  EXPECT_NEAR(read_output(e1).at(0, 50, 58), open, 0.01 * open);  // open ground at 13:00 PDT
  EXPECT_LT(read_output(e2).at(0, 50, 58), 0.5 * open);
}

TEST(CliLighting, ShadedIsGreyForUniformRgbForColourSkiesAndSkyOnlyKeepsTheClassic) {
  ScratchDir dir;
  RasterSpec flat;
  flat.width = flat.height = 9;
  const std::string in = make_raster(dir.file("flat.tif"), flat);
  auto shade = [&](const std::string& name, const std::string& extra) {
    const auto r = run_skylit("shade " + in + " -o " + dir.file(name) + " --azimuths 8 -q" + extra, true);
    EXPECT_EQ(r.status, 0) << r.out;
    return read_output(dir.file(name));
  };
  const Raster classic = shade("classic.png", " --no-sun");
  ASSERT_EQ(classic.bands, 1);
  EXPECT_EQ(classic.at(0, 4, 4), 255.0f);  // open flat ground under the uniform sky: white
  const Raster dflt = shade("default.png", "");
  ASSERT_EQ(dflt.bands, 1);
  // gdaldem's sun (45°) + sky over the zenith-sun reference. A grey sky takes the
  // linear tone (--tone auto): 1 + 254·E/E_ref, E = D + DNI·sin e of the ESRA clear sky.
  auto open_ground = [](double e_deg) {
    const double e = e_deg * kDeg;
    return skylit::sky::esra_diffuse_horizontal(e, 3.0) + skylit::sky::broadband_dni(e, 3.0) * std::sin(e);
  };
  const double x = open_ground(45.0) / open_ground(90.0);
  EXPECT_NEAR(dflt.at(0, 4, 4), 1.0 + std::round(254.0 * x), 1.0);
  const Raster srgb = shade("srgb.png", " --tone srgb");  // the picture's curve, key 0.8
  EXPECT_NEAR(srgb.at(0, 4, 4), skylit::shading::srgb_code_value(0.8 * x), 1.0);
  const Raster colour = shade("colour.png", " --sky preetham -alt 20 -az 135");
  ASSERT_EQ(colour.bands, 3);
  EXPECT_GT(colour.at(0, 4, 4), colour.at(2, 4, 4));  // a low sun is warm
  const Raster colour_srgb = shade("colour_srgb.png", " --sky preetham -alt 20 -az 135 --tone srgb");
  for (int b = 0; b < 3; ++b) EXPECT_EQ(colour.at(b, 4, 4), colour_srgb.at(b, 4, 4));  // colour skies: sRGB
  const Raster night = shade("night.png", " --sky preetham --sun-elevation -25");
  for (int b = 0; b < 3; ++b) EXPECT_EQ(night.at(b, 4, 4), 1.0f);  // black, not nodata
}
