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

// Missing gdaldem or ../shared: skipped, but failed where CI is set.
bool preconditions_met(std::string& why) {
  if (std::system("command -v gdaldem >/dev/null 2>&1 && command -v gdal_translate >/dev/null 2>&1") != 0)
    why = "gdaldem/gdal_translate not on PATH";
  else if (!std::filesystem::exists(shared_dem("mt_st_helens_usgs30_utm10n.tif")))
    why = "../shared/dem is absent";
  return why.empty();
}

#define REQUIRE_GDALDEM()                                          \
  do {                                                             \
    std::string why;                                               \
    if (!preconditions_met(why)) {                                 \
      if (std::getenv("CI")) FAIL() << why << " (CI is set)";      \
      GTEST_SKIP() << why;                                         \
    }                                                              \
  } while (0)

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

TEST(CliHillshade, RejectsTwoVariantsInOneLine) {
  ScratchDir dir;
  expect_clean_shade_failure(dir, "--synthetic --size 16 -p hillshade -combined -igor -o " +
                                      (dir.path() / "x.tif").string(),
                             "at most one of");
}

}  // namespace
}  // namespace skylit::testing
