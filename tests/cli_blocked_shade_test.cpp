// `skylit shade --block-size`: a DEM shaded in blocks, each read with a halo of the
// search distance, equals the whole-field run. Exactly where the method does not depend
// on the window (the march without a pyramid, the 3×3 hillshade); with the default
// pyramid, whose levels are resampled per window, the blocked run is as close to the
// exact march as the whole one. Plus COG output with overviews, void blocks, and errors.
#include "cli_test_util.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using skylit::terrain::testing::ScratchDir;
using skylit::testing::expect_clean_shade_failure;
using skylit::testing::read_output;
using skylit::testing::run_skylit;

std::string scene(const ScratchDir& dir, int size) {
  const std::string path = dir.file("scene" + std::to_string(size) + ".tif");
  EXPECT_EQ(run_skylit("scene -o " + path + " --size " + std::to_string(size) + " -q").status, 0);
  return path;
}

skylit::testing::OutputRaster shade(const ScratchDir& dir, const std::string& args, const std::string& name) {
  const std::string out = dir.file(name);
  const auto r = run_skylit("shade " + args + " -o " + out + " -q", true);
  EXPECT_EQ(r.status, 0) << args << "\n" << r.out;
  return read_output(out);
}

struct Diff {
  double max = 0, rms = 0;
  int nan_mismatch = 0;
};

Diff diff(const skylit::testing::OutputRaster& a, const skylit::testing::OutputRaster& b) {
  Diff d;
  EXPECT_EQ(a.v.size(), b.v.size());
  double sum = 0;
  for (std::size_t k = 0; k < std::min(a.v.size(), b.v.size()); ++k) {
    const double e = std::abs(double(a.v[k]) - b.v[k]);
    d.max = std::max(d.max, e);
    sum += e * e;
  }
  d.rms = std::sqrt(sum / std::max<std::size_t>(1, a.v.size()));
  return d;
}

TEST(BlockedShade, WithoutAPyramidBlocksEqualTheWholeField) {
  ScratchDir dir;
  const std::string dem = scene(dir, 300);
  // 2 km over 30 m texels: a halo of 75 texels around 64-texel cores (25 blocks).
  const std::string knobs = dem + " -p svf --levels none --max-distance 2000";
  const auto whole = shade(dir, knobs, "whole.tif");
  const auto blocked = shade(dir, knobs + " --block-size 64", "blocked.tif");
  ASSERT_EQ(blocked.w, 300);
  EXPECT_EQ(blocked.gt, whole.gt);
  // Float rounding of the GPU's texel positions (relative to each window's origin).
  EXPECT_LT(diff(whole, blocked).max, 2e-5);
  // The CPU reference in double precision: the same 8-bit codes.
  const std::string ref = dem + " -p shaded --levels none --max-distance 2000 --backend reference";
  const Diff codes = diff(shade(dir, ref, "ref_whole.tif"), shade(dir, ref + " --block-size 100", "ref_blocked.tif"));
  EXPECT_EQ(codes.max, 0.0);
}

TEST(BlockedShade, WithThePyramidAsCloseToTheExactMarchAsTheWholeField) {
  ScratchDir dir;
  const std::string dem = scene(dir, 200);
  const std::string knobs = dem + " -p svf --max-distance 1500";
  const auto exact = shade(dir, knobs + " --exact --backend reference", "exact.tif");
  const Diff whole = diff(exact, shade(dir, knobs, "whole.tif"));
  const Diff blocked = diff(exact, shade(dir, knobs + " --block-size 48", "blocked.tif"));
  EXPECT_LT(blocked.rms, 1.1 * whole.rms + 1e-4) << "whole " << whole.rms;
  EXPECT_LT(blocked.max, 1.5 * whole.max + 1e-3) << "whole " << whole.max;
}

TEST(BlockedShade, HillshadeBlocksAreBitExactAndVoidBlocksStayNodata) {
  ScratchDir dir;
  skylit::terrain::testing::RasterSpec s;
  s.width = 230;
  s.height = 170;
  s.nodata = -9999;
  s.values.resize(static_cast<std::size_t>(s.width) * s.height);
  for (int j = 0; j < s.height; ++j)
    for (int i = 0; i < s.width; ++i)
      s.values[static_cast<std::size_t>(j) * s.width + i] =
          (i < 90 && j < 90) ? -9999.0 : 500 + 80 * std::sin(i * 0.07) * std::cos(j * 0.05) + 0.3 * i;
  const std::string dem = skylit::terrain::testing::make_raster(dir.file("voids.tif"), s);
  const auto whole = shade(dir, dem + " -p hillshade -multidirectional", "whole.tif");
  // 40-texel blocks: the first two in each direction lie wholly in the void.
  const auto blocked = shade(dir, dem + " -p hillshade -multidirectional --block-size 40", "blocked.tif");
  EXPECT_EQ(diff(whole, blocked).max, 0.0);
  EXPECT_EQ(blocked.has_nodata, 1);
  EXPECT_EQ(blocked.at(0, 10, 10), static_cast<float>(blocked.nodata));
}

TEST(BlockedShade, CogOutputGetsOverviews) {
  ScratchDir dir;
  const std::string dem = scene(dir, 600);
  const std::string out = dir.file("cog.tif");
  const auto r = run_skylit("shade " + dem + " -p hillshade --block-size 128 -of COG --co BLOCKSIZE=128 -o " + out, true);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("25 blocks"), std::string::npos) << r.out;
  skylit::terrain::testing::ensure_gdal();
  GDALDataset* ds = GDALDataset::Open(out.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY);
  ASSERT_NE(ds, nullptr);
  const char* layout = ds->GetMetadataItem("LAYOUT", "IMAGE_STRUCTURE");
  EXPECT_STREQ(layout ? layout : "", "COG");
  // Halvings until the longer side fits one 128-texel block: 300, 150, 75.
  EXPECT_EQ(ds->GetRasterBand(1)->GetOverviewCount(), 3);
  GDALClose(GDALDataset::ToHandle(ds));
  const auto whole = shade(dir, dem + " -p hillshade", "whole.tif");
  EXPECT_EQ(diff(whole, read_output(out)).max, 0.0);
  EXPECT_EQ(dir.listing(), (std::vector<std::string>{"cog.tif", "scene600.tif", "whole.tif"}));
}

TEST(BlockedShade, AFullDiskFailsInOneLineAndLeavesNothing) {
  ScratchDir dir;
  const std::string dem = scene(dir, 300);
  skylit::terrain::testing::Tmpfs disk(dir.path() / "disk", "128k");  // under the 352 KiB Float32 svf
  SKYLIT_REQUIRE(disk.mounted() ? "" : "cannot mount a tmpfs here (needs root)");
  const std::string out = (dir.path() / "disk" / "svf.tif").string();
  const auto r = run_skylit("shade " + dem + " -p svf --levels none --max-distance 600 --block-size 64 -q -o " + out, true);
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_EQ(skylit::testing::count_lines(r.out), 1) << r.out;
  EXPECT_NE(r.out.find("the disk is full"), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::is_empty(dir.path() / "disk"));
}

TEST(BlockedShade, BadRequestsFailCleanly) {
  ScratchDir dir;
  const std::string dem = scene(dir, 64);
  const std::string out = " -o " + dir.file("out.tif");
  expect_clean_shade_failure(dir, dem + " -p svf --block-size 4" + out, "under 16");
  expect_clean_shade_failure(dir, dem + " -p svf --block-size many" + out, "--block-size 'many'");
  expect_clean_shade_failure(dir, "--synthetic --size 64 -p svf --block-size 32" + out, "skylit scene");
  expect_clean_shade_failure(dir, dem + " -p shadow --block-size 32 --time 2026-06-21T06:00Z/2026-06-21T08:00Z/PT1H" + out,
                             "not supported");
  expect_clean_shade_failure(dir, dem + " -p shadow --block-size 32 --time 2026-06-21T06:00Z --track x.igc" + out,
                             "--spheres");
}

}  // namespace
