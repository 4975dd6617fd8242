// Synthetic terrain (determinism, range, relief) and the analytic test scenes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "terrain/analytic_scenes.h"
#include "terrain/synthetic.h"

namespace skylit::terrain {
namespace {

// Mean slope angle (degrees) by central differences over the interior.
double mean_slope_deg(const HeightField& f) {
  double sum = 0;
  int n = 0;
  for (int j = 1; j + 1 < f.height; ++j)
    for (int i = 1; i + 1 < f.width; ++i) {
      const double gx = (f.at(i + 1, j) - f.at(i - 1, j)) / (2 * f.dx(j));
      const double gy = (f.at(i, j - 1) - f.at(i, j + 1)) / (2 * f.dy);
      sum += std::atan(std::hypot(gx, gy)) * 180 / M_PI;
      ++n;
    }
  return sum / n;
}

TEST(TerrainSynthetic, DefaultSceneIs512At30m) {
  const HeightField f = default_scene();
  EXPECT_EQ(f.width, 512);
  EXPECT_EQ(f.height, 512);
  EXPECT_DOUBLE_EQ(f.dy, 30.0);
  EXPECT_DOUBLE_EQ(f.dx(100), 30.0);
  EXPECT_FALSE(f.any_nodata());
  EXPECT_TRUE(f.georef.crs_wkt.empty());
  const auto [lo, hi] = std::minmax_element(f.heights.begin(), f.heights.end());
  EXPECT_NEAR(*lo, 400.0, 1e-3);   // base_height
  EXPECT_NEAR(*hi, 2200.0, 1e-3);  // base_height + relief
  // Mountains, not a plane nor a wall of noise: typical alpine mean slopes.
  const double slope = mean_slope_deg(f);
  EXPECT_GT(slope, 5.0);
  EXPECT_LT(slope, 45.0);
}

TEST(TerrainSynthetic, DeterministicPerSeed) {
  SyntheticOptions o;
  o.width = 96;
  o.height = 64;
  o.seed = 42;
  const HeightField a = make_synthetic_terrain(o), b = make_synthetic_terrain(o);
  EXPECT_EQ(a.heights, b.heights);
  o.seed = 43;
  const HeightField c = make_synthetic_terrain(o);
  EXPECT_NE(a.heights, c.heights);
}

TEST(TerrainSynthetic, ValleyIsCarved) {
  SyntheticOptions o;
  o.width = o.height = 256;
  const HeightField carved = make_synthetic_terrain(o);
  o.carve_valley = false;
  const HeightField plain = make_synthetic_terrain(o);
  // Along every column the carved scene's lowest point is a flat-floored valley: its
  // minimum sits well below the same column of the uncarved scene, relative to range.
  auto column_min_rel = [](const HeightField& f, int i) {
    float lo = 1e30f;
    for (int j = 0; j < f.height; ++j) lo = std::min(lo, f.at(i, j));
    return (lo - 400.0) / 1800.0;
  };
  double carved_sum = 0, plain_sum = 0;
  for (int i = 0; i < 256; i += 8) carved_sum += column_min_rel(carved, i), plain_sum += column_min_rel(plain, i);
  EXPECT_LT(carved_sum, plain_sum);
}

TEST(TerrainSynthetic, RejectsBadOptions) {
  SyntheticOptions o;
  o.width = 1;
  EXPECT_THROW(make_synthetic_terrain(o), std::invalid_argument);
  o = {};
  o.spacing = 0;
  EXPECT_THROW(make_synthetic_terrain(o), std::invalid_argument);
  o = {};
  o.octaves = 0;
  EXPECT_THROW(make_synthetic_terrain(o), std::invalid_argument);
}

TEST(TerrainAnalytic, FlatAndTilted) {
  const HeightField flat = flat_plane(5, 4, 2.0, 7.0);
  for (float z : flat.heights) EXPECT_EQ(z, 7.0f);
  // Centre at texel (2, 1.5); metric x = (i − 2)·dx east, y = (1.5 − j)·dx north.
  const HeightField t = tilted_plane(5, 4, 2.0, 0.5, -0.25, 100.0);
  EXPECT_FLOAT_EQ(t.at(4, 0), 100 + 0.5 * 4 - 0.25 * 3);
  EXPECT_FLOAT_EQ(t.at(0, 3), 100 - 0.5 * 4 + 0.25 * 3);
}

TEST(TerrainAnalytic, CircularPit) {
  const double dx = 1.0, r = 20.0, depth = 10.0;
  const HeightField p = circular_pit(101, 101, dx, r, depth);
  EXPECT_EQ(p.at(50, 50), -10.0f);
  EXPECT_EQ(p.at(50, 30), -10.0f);  // on the rim (distance exactly r)
  EXPECT_EQ(p.at(50, 29), 0.0f);
  EXPECT_EQ(p.at(0, 0), 0.0f);
  const auto pit_texels = std::count(p.heights.begin(), p.heights.end(), -10.0f);
  EXPECT_NEAR(static_cast<double>(pit_texels), M_PI * r * r, 0.03 * M_PI * r * r);  // Gauss circle problem
}

TEST(TerrainAnalytic, LongWallAndHill) {
  const HeightField w = long_wall(40, 10, 5.0, 50.0, 10.0, 100.0);  // axis at column 20
  for (int j = 0; j < 10; ++j) {
    EXPECT_EQ(w.at(19, j), 50.0f);
    EXPECT_EQ(w.at(20, j), 50.0f);
    EXPECT_EQ(w.at(21, j), 50.0f);
    EXPECT_EQ(w.at(22, j), 0.0f);
    EXPECT_EQ(w.at(18, j), 0.0f);
  }
  const HeightField g = gaussian_hill(41, 41, 10.0, 200.0, 50.0);
  EXPECT_FLOAT_EQ(g.at(20, 20), 200.0f);
  EXPECT_NEAR(g.at(25, 20), 200.0 * std::exp(-0.5), 1e-3);  // one sigma east
}

}  // namespace
}  // namespace skylit::terrain
