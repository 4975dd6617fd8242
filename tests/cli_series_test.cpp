// `skylit shade --time` series end to end: one process, one renderer, a frame per time.
// A 24-frame series on a real DEM writes 24 frames that equal single-time runs at the
// same times (multi-band GeoTIFF with the times as band descriptions, and one file per
// frame through a %d pattern); insolation and sun-hours sum the frames; bad series get
// one clear line and leave no file.
#include "cli_test_util.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

namespace skylit::testing {
namespace {

namespace fs = std::filesystem;

// Olinda (UTM 25S), 111 × 111 at 30 m; local time UTC−3.
const std::string kDem = std::string(SKYLIT_SHARED_DIR) + "/dem/olinda_dem_utm25s.tif";
// 06:00 … 17:30 every 30 min: 24 frames.
const std::string kSeries = "2026-06-21T06:00-03:00/2026-06-21T17:30-03:00/PT30M";

std::string time_of_frame(int k) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "2026-06-21T%02d:%02d:00Z", 9 + k / 2, k % 2 ? 30 : 0);
  return buf;
}

bool same_band(const OutputRaster& a, int band_a, const OutputRaster& b, int band_b) {
  const std::size_t n = static_cast<std::size_t>(a.w) * a.h;
  return a.w == b.w && a.h == b.h &&
         std::memcmp(a.v.data() + band_a * n, b.v.data() + band_b * n, n * sizeof(float)) == 0;
}

GDALDataset* open_raster(const std::string& path) {
  return GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY);
}

TEST(CliSeries, TwentyFourFramesEqualSingleTimeRuns) {
  if (!fs::exists(kDem)) {
    if (std::getenv("CI")) FAIL() << kDem << " is absent, and CI has ../shared beside the clone";
    GTEST_SKIP() << kDem << " is absent";
  }
  terrain::testing::ScratchDir dir;
  for (const std::string product : {"shadow", "irradiance"}) {
    const std::string series = dir.file(product + "_series.tif");
    const auto r = run_skylit("shade " + kDem + " -p " + product + " --time " + kSeries + " -o " + series, true);
    ASSERT_EQ(r.status, 0) << r.out;
    const OutputRaster all = read_output(series);
    ASSERT_EQ(all.bands, 24);
    GDALDataset* ds = open_raster(series);
    ASSERT_NE(ds, nullptr);
    for (int k = 0; k < 24; ++k)
      EXPECT_EQ(std::string(ds->GetRasterBand(k + 1)->GetDescription()), time_of_frame(k)) << "band " << k + 1;
    GDALClose(GDALDataset::ToHandle(ds));
    for (int k : {0, 7, 12, 23}) {
      const std::string one = dir.file(product + "_" + std::to_string(k) + ".tif");
      ASSERT_EQ(run_skylit("shade " + kDem + " -q -p " + product + " --time " + time_of_frame(k) + " -o " + one).status, 0);
      EXPECT_TRUE(same_band(all, k, read_output(one), 0)) << product << " frame " << k;
    }
    if (product == "shadow") {  // a visible disc fraction, and sun on most of the ground at noon
      for (float v : all.v) EXPECT_TRUE(v == static_cast<float>(all.nodata) || (v >= 0.0f && v <= 1.0f)) << v;
      EXPECT_GT(all.mean(12), 0.5);
    }
  }
  // One file per frame: the same frames.
  const auto r = run_skylit("shade " + kDem + " -q -p shaded --time " + kSeries + " -o " + dir.file("f_%02d.png"));
  ASSERT_EQ(r.status, 0) << r.out;
  for (int k = 0; k < 24; ++k) ASSERT_TRUE(fs::exists(dir.file((k < 10 ? "f_0" : "f_") + std::to_string(k) + ".png")));
  const std::string single = dir.file("single.png");
  ASSERT_EQ(run_skylit("shade " + kDem + " -q -p shaded --time " + time_of_frame(5) + " -o " + single).status, 0);
  EXPECT_TRUE(same_band(read_output(dir.file("f_05.png")), 0, read_output(single), 0));
}

TEST(CliSeries, SumsOverADayAreTheFramesSums) {
  terrain::testing::ScratchDir dir;
  const std::string dem = dir.file("scene.tif");
  ASSERT_EQ(run_skylit("scene --size 48 -o " + dem).status, 0);
  const std::string times = "2026-03-20T06:00Z/2026-03-20T18:00Z/PT1H";  // 13 frames at UTM 32N
  ASSERT_EQ(run_skylit("shade " + dem + " -q -p irradiance --time " + times + " -o " + dir.file("e.tif")).status, 0);
  ASSERT_EQ(run_skylit("shade " + dem + " -q -p insolation --time " + times + " -o " + dir.file("i.tif")).status, 0);
  ASSERT_EQ(run_skylit("shade " + dem + " -q -p shadow --time " + times + " -o " + dir.file("s.tif")).status, 0);
  ASSERT_EQ(run_skylit("shade " + dem + " -q -p sun-hours --time " + times + " -o " + dir.file("h.tif")).status, 0);
  const OutputRaster e = read_output(dir.file("e.tif")), i = read_output(dir.file("i.tif"));
  const OutputRaster s = read_output(dir.file("s.tif")), h = read_output(dir.file("h.tif"));
  ASSERT_EQ(e.bands, 13);
  ASSERT_EQ(i.bands, 1);
  // Trapezoid over 1-h steps: half weights at the ends. Sun hours count only frames
  // whose sun is above the horizon; at 18:00Z (9° E) it is 6° below, shadow 0 anyway.
  for (int j = 0; j < e.h; j += 7)
    for (int x = 0; x < e.w; x += 7) {
      double wh = 0.0, hours = 0.0;
      for (int k = 0; k < 13; ++k) {
        const double w = k == 0 || k == 12 ? 0.5 : 1.0;
        wh += w * e.at(k, x, j);
        hours += w * s.at(k, x, j);
      }
      EXPECT_NEAR(i.at(0, x, j), wh, 1e-4 * wh + 1e-3) << x << "," << j;
      EXPECT_NEAR(h.at(0, x, j), hours, 1e-4) << x << "," << j;
    }
}

TEST(CliSeries, BadSeriesGetOneClearLineAndNoFile) {
  terrain::testing::ScratchDir dir;
  const std::string dem = dir.file("scene.tif");
  ASSERT_EQ(run_skylit("scene --size 16 -o " + dem).status, 0);
  terrain::testing::ScratchDir out;
  const std::string base = dem + " -p shadow -o " + out.file("x.tif") + " --time ";
  expect_clean_shade_failure(out, base + "2026-06-21T04:00Z/2026-06-21T20:00", "needs a step");
  expect_clean_shade_failure(out, base + "2026-06-21T04:00Z/2026-06-21T20:00Z/PTXM", "--time");
  expect_clean_shade_failure(out, base + "2026-06-21T04:00Z/2026-06-21T20:00Z/PT0M", "step must be positive");
  expect_clean_shade_failure(out, base + "2026-06-21T04:00Z/2026-06-21T20:00Z/-PT10M", "step must be positive");
  expect_clean_shade_failure(out, base + "2026-06-21T20:00Z/2026-06-21T04:00Z/PT10M", "before the start");
  expect_clean_shade_failure(out, base + "2026-06-01T00:00Z/2026-06-30T00:00Z/PT1M", "--max-frames");
  expect_clean_shade_failure(out, dem + " -p shaded -o " + out.file("x.png") + " --time 2026-06-21T08:00Z,2026-06-21T09:00Z",
                             "%d");
  expect_clean_shade_failure(out, dem + " -p svf -o " + out.file("x.tif") + " --time 2026-06-21", "lit by the sun");
  expect_clean_shade_failure(out, dem + " -p insolation -o " + out.file("x.tif"), "sums over time");
  expect_clean_shade_failure(out, dem + " -p insolation -o " + out.file("x.tif") + " --time 2026-06-21T08:00Z",
                             "no interval");
  expect_clean_shade_failure(out, dem + " -p shadow -o " + out.file("f_%d_%d.png") + " --time 2026-06-21",
                             "two frame numbers");
  // The limit is a switch, not a wall.
  EXPECT_EQ(run_skylit("shade " + base + "2026-06-21T04:00Z/2026-06-21T04:30Z/PT1M --max-frames 20").status, 1);
  EXPECT_EQ(run_skylit("shade " + base + "2026-06-21T04:00Z/2026-06-21T04:30Z/PT1M --max-frames 40").status, 0);
}

}  // namespace
}  // namespace skylit::testing
