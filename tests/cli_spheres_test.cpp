// `skylit shade --spheres FILE.csv` end to end: a sphere given in the DEM's CRS casts its
// shadow where the projection along the sun puts it (closed form over a flat UTM DEM),
// darkens the skyview below it by sin²α, leaves horizon and svf alone (with a note), and
// bad files fail with one line naming the line, leaving no output.
#include "cli_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <string>

using skylit::testing::expect_clean_shade_failure;
using skylit::testing::read_output;
using skylit::testing::run_skylit;
using namespace skylit::terrain::testing;

namespace {

// A flat 80×60 DEM at 100 m height, 2 m texels, UTM 32N with its corner at (500000, 5000000).
std::string flat_dem(const ScratchDir& dir) {
  RasterSpec s;
  s.width = 80;
  s.height = 60;
  s.values.assign(80 * 60, 100.0f);
  s.epsg = 32632;
  s.gt = {500000.0, 2.0, 0, 5000000.0, 0, -2.0};
  return make_raster(dir.file("flat.tif"), s);
}

std::string write(const ScratchDir& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir.file(name)) << text;
  return dir.file(name);
}

TEST(CliSpheres, ShadowLandsWhereTheSunProjectsTheSphere) {
  ScratchDir dir;
  const std::string dem = flat_dem(dir);
  // Sphere r = 8 m, 40 m above the ground at (500100, 4999940): with the sun due south at
  // 45°, its shadow is centred 40 m north, an ellipse of semi-axes 8 m (E–W) and 8√2 m.
  const std::string csv = write(dir, "s.csv", "x,y,z,radius\n500100,4999940,140,8\n");
  const std::string out = dir.file("shadow.tif");
  const auto r = run_skylit("shade " + dem + " -o " + out + " -p shadow --sun-azimuth 180 --sun-elevation 45 --spheres " +
                                csv + " -q",
                            true);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto shadow = read_output(out).v;
  int dark = 0;
  double sum_x = 0, sum_y = 0;
  for (int j = 0; j < 60; ++j)
    for (int i = 0; i < 80; ++i)
      if (shadow[j * 80 + i] < 0.5f) {
        ++dark;
        sum_x += 500000.0 + (i + 0.5) * 2.0;
        sum_y += 5000000.0 - (j + 0.5) * 2.0;
      }
  const double area = std::numbers::pi * 8.0 * 8.0 * std::sqrt(2.0) / 4.0;  // texels
  EXPECT_NEAR(dark, area, 0.08 * area);
  EXPECT_NEAR(sum_x / dark, 500100.0, 1.0);
  EXPECT_NEAR(sum_y / dark, 4999980.0, 1.0);
}

TEST(CliSpheres, SkyviewBelowTheSphereAndTerrainOnlyProducts) {
  ScratchDir dir;
  const std::string dem = flat_dem(dir);
  const std::string csv = write(dir, "s.csv", "# one sphere\nx,y,z,radius\n500081,4999941,120,4\n");
  const std::string out = dir.file("sky.tif");
  ASSERT_EQ(run_skylit("shade " + dem + " -o " + out + " -p skyview --backend reference -q --spheres " + csv).status, 0);
  const double below = read_output(out).v[29 * 80 + 40];  // texel centre (500081, 4999941)
  EXPECT_NEAR(below, 1.0 - 0.2 * 0.2, 0.065 * 0.04);      // 1 − sin²α, r/d = 4/20
  // The GPU backend (llvmpipe in CI) shades the same sphere, within the float tolerance.
  const std::string gpu_out = dir.file("sky_gpu.tif");
  const auto gpu = run_skylit("shade " + dem + " -o " + gpu_out + " -p skyview --backend gpu -q --spheres " + csv, true);
  ASSERT_EQ(gpu.status, 0) << gpu.out;
  EXPECT_NEAR(read_output(gpu_out).v[29 * 80 + 40], below, 2e-3);
  const auto svf = run_skylit("shade " + dem + " -o " + dir.file("svf.tif") + " -p svf --spheres " + csv, true);
  EXPECT_EQ(svf.status, 0) << svf.out;
  EXPECT_NE(svf.out.find("svf is the terrain's alone"), std::string::npos) << svf.out;
}

TEST(CliSpheres, BadFilesFailWithOneLine) {
  ScratchDir dir;
  const std::string dem = flat_dem(dir);
  const std::string base = dem + " -o " + dir.file("x.tif") + " -p shadow --spheres ";
  expect_clean_shade_failure(dir, base + dir.file("missing.csv"), "cannot read");
  expect_clean_shade_failure(dir, base + write(dir, "e.csv", ""), "is empty");
  expect_clean_shade_failure(dir, base + write(dir, "h.csv", "a,b,c\n1,2,3\n"), "h.csv:1: the header");
  expect_clean_shade_failure(dir, base + write(dir, "n.csv", "x,y,z,radius\n1,2,3,4\n1,2,x,4\n"), "n.csv:3: 'x'");
  expect_clean_shade_failure(dir, base + write(dir, "r.csv", "x,y,z,radius\n1,2,3,0\n"), "r.csv:2: the radius");
  expect_clean_shade_failure(dir, base + write(dir, "c.csv", "x,y,z,radius\n1,2,3\n"), "expected 4 values");
  expect_clean_shade_failure(dir, base + write(dir, "o.csv", "x,y,z,radius\n"), "no spheres");
  expect_clean_shade_failure(dir, base + write(dir, "g.csv", "x,y,z,radius\n1,2,3,4\n") + " --blocker-error -1",
                             "--blocker-error must be");
  expect_clean_shade_failure(dir, base + write(dir, "g.csv", "x,y,z,radius\n1,2,3,4\n") + " --blocker-merge 0.7",
                             "--blocker-merge must be");
}

}  // namespace
