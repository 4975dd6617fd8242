// `skylit shade -p hillshade` against Debian's gdaldem itself, run by the test on crops
// of the shared DEMs: every pixel of every variant and algorithm must be equal.
#include "cli_test_util.h"
#include "terrain_test_util.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

namespace skylit::testing {
namespace {

using terrain::testing::ScratchDir;
using terrain::testing::shared_dem;

// What the tests need and lack ("": nothing): gdaldem, gdal_translate, ../shared.
std::string missing_gdaldem() {
  if (std::system("command -v gdaldem >/dev/null 2>&1 && command -v gdal_translate >/dev/null 2>&1") != 0)
    return "gdaldem/gdal_translate not on PATH";
  if (!std::filesystem::exists(shared_dem("mt_st_helens_usgs30_utm10n.tif"))) return "../shared/dem is absent";
  return "";
}
#define REQUIRE_GDALDEM() SKYLIT_REQUIRE(missing_gdaldem())

int sh(const std::string& cmd) { return std::system((cmd + " >/dev/null 2>&1").c_str()); }

// Pixels that differ between two single-band rasters (−1 when sizes differ or unreadable).
long differing_pixels(const OutputRaster& a, const OutputRaster& b) {
  if (a.w == 0 || a.w != b.w || a.h != b.h || a.bands != b.bands) return -1;
  long n = 0;
  for (std::size_t k = 0; k < a.v.size(); ++k) n += a.v[k] != b.v[k];
  return n;
}

struct Crop {
  std::string name, file, srcwin, extra;  // extra: gdal_translate options (nodata), and the -s
  std::string scale;
};

TEST(CliHillshade, EqualsGdaldemOnEveryVariant) {
  REQUIRE_GDALDEM();
  ScratchDir dir;
  const std::vector<Crop> crops = {
      {"helens_int16_nodata", "mt_st_helens_usgs30_utm10n.tif", "100 100 300 300", "", ""},  // Int16, voids
      {"slovenia_float", "slovenia_lidar1m_d96tm.tif", "300 300 300 300", "", ""},
      {"slovenia_float_nodata", "slovenia_lidar1m_d96tm.tif", "300 300 300 300", "-a_nodata 300", ""},
      {"pyrenees_4326", "pyrenees_andorra_srtm3_4326.tif", "200 200 300 300", "", "-s 111120"},
      {"olinda_odd_width", "olinda_dem_utm25s.tif", "0 0 111 111", "", ""},
  };
  const std::vector<std::string> variants = {
      "",
      "-compute_edges",
      "-combined",
      "-multidirectional",
      "-igor",
      "-alg ZevenbergenThorne",
      "-alg ZevenbergenThorne -combined -compute_edges",
      "-alg ZevenbergenThorne -multidirectional",
      "-alg ZevenbergenThorne -igor",
      "-z 2.5 -az 200 -alt 30 -compute_edges",
      "-multidirectional -z 3 -alt 60",
  };
  for (const Crop& c : crops) {
    const std::string in = (dir.path() / (c.name + ".tif")).string();
    ASSERT_EQ(sh("gdal_translate -q -srcwin " + c.srcwin + " " + c.extra + " " + shared_dem(c.file) + " " + in), 0);
    for (std::size_t v = 0; v < variants.size(); ++v) {
      const std::string flags = variants[v] + " " + c.scale;
      const std::string ref = (dir.path() / (c.name + "_gdaldem" + std::to_string(v) + ".tif")).string();
      const std::string got = (dir.path() / (c.name + "_skylit" + std::to_string(v) + ".tif")).string();
      ASSERT_EQ(sh("gdaldem hillshade -q " + in + " " + ref + " " + flags), 0) << flags;
      const auto r = run_skylit("shade " + in + " -o " + got + " -p hillshade -q " + flags, true);
      ASSERT_EQ(r.status, 0) << flags << "\n" << r.out;
      const OutputRaster a = read_output(ref), b = read_output(got);
      EXPECT_EQ(b.type, GDT_Byte);
      EXPECT_TRUE(b.has_nodata && b.nodata == 0.0);
      EXPECT_EQ(differing_pixels(a, b), 0) << c.name << " " << flags << ": pixels differing from gdaldem";
    }
  }
}

// -b, --nodata and -of with a copy-only driver, each against the gdaldem run it equals.
TEST(CliHillshade, BandNodataAndAnyDriver) {
  REQUIRE_GDALDEM();
  ScratchDir dir;
  const auto at = [&](const std::string& n) { return (dir.path() / n).string(); };
  const std::string dem = shared_dem("slovenia_lidar1m_d96tm.tif");
  // Band 2 of a two-band VRT is a crop with a nodata value gdaldem is given; skylit gets
  // the same band without nodata and --nodata 300.
  ASSERT_EQ(sh("gdal_translate -q -srcwin 300 300 200 200 -a_nodata 300 " + dem + " " + at("nd.tif")), 0);
  ASSERT_EQ(sh("gdal_translate -q -srcwin 300 300 200 200 -a_nodata none " + dem + " " + at("plain.tif")), 0);
  ASSERT_EQ(sh("gdalbuildvrt -q -separate " + at("two.vrt") + " " + at("plain.tif") + " " + at("plain.tif")), 0);
  ASSERT_EQ(sh("gdaldem hillshade -q " + at("nd.tif") + " " + at("ref.tif")), 0);
  auto r = run_skylit("shade " + at("two.vrt") + " -b 2 --nodata 300 -p hillshade -q -o " + at("got.tif"), true);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(differing_pixels(read_output(at("ref.tif")), read_output(at("got.tif"))), 0);
  // The CPU reference renderer hands the local product to the same function as the GPU one
  // (auto above): equal too, with -co passed through.
  r = run_skylit("shade " + at("nd.tif") + " --backend reference -co COMPRESS=DEFLATE -p hillshade -q -o " +
                     at("ref_backend.tif"),
                 true);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(differing_pixels(read_output(at("ref.tif")), read_output(at("ref_backend.tif"))), 0);
  // A copy-only driver (AAIGrid has CreateCopy alone).
  ASSERT_EQ(sh("gdaldem hillshade -q -of AAIGrid " + at("nd.tif") + " " + at("ref.asc")), 0);
  r = run_skylit("shade " + at("nd.tif") + " -of AAIGrid -p hillshade -q -o " + at("got.asc"), true);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(differing_pixels(read_output(at("ref.asc")), read_output(at("got.asc"))), 0);
  expect_clean_shade_failure(dir, at("nd.tif") + " -b 3 -p hillshade -o " + at("b3.tif"), "band 3 does not exist");
  expect_clean_shade_failure(dir, at("nd.tif") + " -of NoSuchDriver -p hillshade -o " + at("x.tif"),
                             "unknown output format 'NoSuchDriver'");
}

// --xscale/--yscale (gdaldem ≥ 3.11; Debian's 3.6 has only -s): equal scales are -s, and
// an east–west scale of 2 equals gdaldem on the same heights with pixels twice as wide.
TEST(CliHillshade, AxisScalesEqualGdaldemOnStretchedPixels) {
  REQUIRE_GDALDEM();
  ScratchDir dir;
  const auto at = [&](const std::string& n) { return (dir.path() / n).string(); };
  ASSERT_EQ(sh("gdal_translate -q -srcwin 200 200 150 120 " + shared_dem("pyrenees_andorra_srtm3_4326.tif") + " " +
               at("geo.tif")),
            0);
  ASSERT_EQ(sh("gdaldem hillshade -q -s 111120 " + at("geo.tif") + " " + at("ref_s.tif")), 0);
  auto r = run_skylit("shade " + at("geo.tif") + " --xscale 111120 --yscale 111120 -p hillshade -q -o " + at("xy.tif"),
                      true);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(differing_pixels(read_output(at("ref_s.tif")), read_output(at("xy.tif"))), 0);
  // A projected crop (1 m lidar) and the same heights on 2 m × 1 m pixels.
  ASSERT_EQ(sh("gdal_translate -q -srcwin 300 300 160 140 " + shared_dem("slovenia_lidar1m_d96tm.tif") + " " +
               at("m.tif")),
            0);
  ASSERT_EQ(sh("gdal_translate -q -a_ullr 0 140 320 0 " + at("m.tif") + " " + at("wide.tif")), 0);
  ASSERT_EQ(sh("gdaldem hillshade -q -compute_edges " + at("wide.tif") + " " + at("ref_wide.tif")), 0);
  r = run_skylit("shade " + at("m.tif") + " --xscale 2 --yscale 1 -compute_edges -p hillshade -q -o " + at("x2.tif"),
                 true);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(differing_pixels(read_output(at("ref_wide.tif")), read_output(at("x2.tif"))), 0);
}

TEST(CliHillshade, RejectsTwoVariantsInOneLine) {
  ScratchDir dir;
  expect_clean_shade_failure(dir, "--synthetic --size 16 -p hillshade -combined -igor -o " +
                                      (dir.path() / "x.tif").string(),
                             "at most one of");
}

}  // namespace
}  // namespace skylit::testing
