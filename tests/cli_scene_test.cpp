// `skylit scene`: the built-in scene as a GeoTIFF holds exactly the heights that
// `shade --synthetic` shades (checked against the library's own scene, read back
// through GDAL), with metric georeferencing, and never overwrites by accident.
#include "cli_test_util.h"
#include "terrain_test_util.h"

#include "terrain/synthetic.h"

#include <gtest/gtest.h>

using skylit::testing::read_output;
using skylit::testing::run_skylit;
using namespace skylit::terrain::testing;

TEST(CliScene, WritesTheSyntheticSceneAsAProjectedGeoTiff) {
  ScratchDir dir;
  const std::string out = dir.file("scene.tif");
  ASSERT_EQ(run_skylit("scene -o " + out + " --size 40 --seed 7 -q").status, 0);
  const auto r = read_output(out);
  ASSERT_EQ(r.w, 40);
  ASSERT_EQ(r.h, 40);
  EXPECT_EQ(r.type, GDT_Float32);
  EXPECT_NE(r.crs_name.find("UTM zone 32N"), std::string::npos) << r.crs_name;
  skylit::terrain::SyntheticOptions o;
  o.width = o.height = 40;
  o.seed = 7;
  const auto f = skylit::terrain::make_synthetic_terrain(o);
  EXPECT_DOUBLE_EQ(r.gt[1], o.spacing);
  EXPECT_DOUBLE_EQ(r.gt[5], -o.spacing);
  for (int j = 0; j < 40; ++j)
    for (int i = 0; i < 40; ++i) ASSERT_EQ(r.at(0, i, j), f.at(i, j)) << i << "," << j;

  // The file shades like the built-in scene.
  ASSERT_EQ(run_skylit("shade " + out + " -o " + dir.file("a.tif") + " -p svf --azimuths 8 -q").status, 0);
  ASSERT_EQ(run_skylit("shade --synthetic --size 40 --seed 7 -o " + dir.file("b.tif") + " -p svf --azimuths 8 -q").status, 0);
  const auto a = read_output(dir.file("a.tif")), b = read_output(dir.file("b.tif"));
  ASSERT_EQ(a.v.size(), b.v.size());
  for (std::size_t k = 0; k < a.v.size(); ++k) ASSERT_NEAR(a.v[k], b.v[k], 1e-5) << k;

  // No accidental overwrite; --overwrite replaces.
  const auto again = run_skylit("scene -o " + out + " --size 8 -q", true);
  EXPECT_EQ(again.status, 1);
  EXPECT_NE(again.out.find("--overwrite"), std::string::npos) << again.out;
  EXPECT_EQ(read_output(out).w, 40);
  ASSERT_EQ(run_skylit("scene -o " + out + " --size 8 --overwrite -q").status, 0);
  EXPECT_EQ(read_output(out).w, 8);
}
