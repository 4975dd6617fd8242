// `skylit shade --time` series end to end: one process, one renderer, a frame per time.
// A 24-frame series on a real DEM writes 24 frames that equal single-time runs at the
// same times (multi-band GeoTIFF with the times as band descriptions, and one file per
// frame through a %d pattern); insolation and sun-hours sum the frames; bad series get
// one clear line and leave no file.
#include "cli_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
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

// Mean |a − b| of band k of two rasters over the texels valid in both.
double mean_abs_difference(const OutputRaster& a, int band_a, const OutputRaster& b, int band_b) {
  const std::size_t n = static_cast<std::size_t>(a.w) * a.h;
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t t = 0; t < n; ++t) {
    const double x = a.v[band_a * n + t], y = b.v[band_b * n + t];
    if (x == a.nodata || y == b.nodata) continue;
    sum += std::abs(x - y);
    ++count;
  }
  return count ? sum / static_cast<double>(count) : 0.0;
}

// A replay's frames seconds apart keep the sun's swept far horizon while its heading moves
// less than --sun-tolerance (0.05° by default): against the dense exact march (--exact)
// they stay as close as frames swept afresh (within 1.5×, the bound of the viewer's
// reuse), and --sun-tolerance 0 sweeps every frame, equal to single-time runs.
TEST(CliSeries, ReplayKeepsTheSunsFarHorizonWithinItsBound) {
  terrain::testing::ScratchDir dir;
  const std::string dem = dir.file("scene.tif");  // 47° N: the sun 10° up at 05:00Z
  ASSERT_EQ(run_skylit("scene --size 128 -o " + dem).status, 0);
  // 11 frames 4 s apart: the sun's heading moves 0.15° in all.
  const std::string replay = "shade " + dem + " -p shadow --time 2026-06-21T05:00:00Z/2026-06-21T05:00:40Z/PT4S --timings ";
  const auto kept = run_skylit(replay + "-o " + dir.file("kept.tif"), true);
  ASSERT_EQ(kept.status, 0) << kept.out;
  const auto swept = run_skylit(replay + "--sun-tolerance 0 -o " + dir.file("swept.tif"), true);
  ASSERT_EQ(swept.status, 0) << swept.out;
  const auto exact = run_skylit(replay + "--exact -o " + dir.file("exact.tif"), true);
  ASSERT_EQ(exact.status, 0) << exact.out;
  const auto frames_kept = [](const std::string& out) {
    const std::string label = "frames keeping the sun's far";
    const std::size_t at = out.find(label);
    return at == std::string::npos ? -1 : std::atoi(out.c_str() + at + label.size());
  };
  if (kept.out.find("on gpu") != std::string::npos) {  // CI: llvmpipe at least (SKYLIT_REQUIRE_GPU)
    EXPECT_GE(frames_kept(kept.out), 6) << kept.out;
  }
  EXPECT_EQ(frames_kept(swept.out), 0) << swept.out;

  const OutputRaster k = read_output(dir.file("kept.tif")), s = read_output(dir.file("swept.tif")),
                     e = read_output(dir.file("exact.tif"));
  ASSERT_EQ(k.bands, 11);
  double kept_error = 0.0, swept_error = 0.0;
  for (int b = 0; b < 11; ++b) {
    kept_error += mean_abs_difference(k, b, e, b) / 11;
    swept_error += mean_abs_difference(s, b, e, b) / 11;
  }
  std::printf("mean |shadow - exact|: kept %.3g, swept %.3g\n", kept_error, swept_error);
  EXPECT_LE(kept_error, 1.5 * swept_error) << "kept " << kept_error << ", swept " << swept_error;
  EXPECT_GT(swept_error, 0.0);  // the sweep is not the exact march: the bound is not vacuous
  EXPECT_GT(e.mean(10), 0.2);   // and the sun is up on much of the ground

  const std::string single = dir.file("single.tif");
  ASSERT_EQ(run_skylit("shade " + dem + " -q -p shadow --time 2026-06-21T05:00:28Z -o " + single).status, 0);
  EXPECT_TRUE(same_band(s, 7, read_output(single), 0));
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

// A polar night has no sunrise (at 80° N on 21 December the sun culminates at
// 90° − 80° − 23.44° = −13.4°): a day's sums are 0 everywhere, and the run says why
// without reporting frames it never computed.
TEST(CliSeries, APolarNightSumsToZeroAndSaysSo) {
  terrain::testing::ScratchDir dir;
  const std::string dem = dir.file("scene.tif");
  ASSERT_EQ(run_skylit("scene --size 16 -o " + dem).status, 0);
  for (const std::string product : {"insolation", "sun-hours"}) {
    const std::string out = dir.file(product + ".tif");
    const auto r = run_skylit("shade " + dem + " -p " + product + " --time 2026-12-21 --lat 80 --lon 10 -o " + out, true);
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find("note: polar night on 2026-12-21"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("times from"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("computed"), std::string::npos) << r.out;
    const OutputRaster v = read_output(out);
    ASSERT_EQ(v.bands, 1);
    for (int j = 0; j < v.h; ++j)
      for (int i = 0; i < v.w; ++i) ASSERT_EQ(v.at(0, i, j), 0.0f) << product << " at " << i << "," << j;
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
