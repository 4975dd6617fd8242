// The tile windows' approximate transform (terrain/zoom_transform.h) against the exact
// PROJ transform it replaces: the largest error in source pixels at zooms 8–15 on a UTM
// and a geographic DEM (printed), within the node rule's bound and well under 0.01 px;
// and the approximation's independence of the window that asks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "terrain/dem_reader.h"
#include "terrain/tile_window.h"
#include "terrain/zoom_transform.h"
#include "terrain_test_util.h"

namespace skylit::terrain {
namespace {

std::string dem_path(const char* name) { return std::string(SKYLIT_SHARED_DIR) + "/dem/" + name; }

// Global pixel coordinates of DEM pixel (px, py) at zoom z.
void global_of(const NodeGrid& g, double px, double py, double& gx, double& gy) {
  ASSERT_TRUE(g.global_pixel(px, py, gx, gy));
}

struct Errors {
  double x = 0, y = 0;  // largest |approximate − exact| per source axis, source pixels
};

// Over a 128² patch of pixel centres and corners (the warper asks for both) whose
// top-left is global pixel (gx0, gy0).
Errors patch_errors(const NodeGrid& g, long long gx0, long long gy0) {
  Errors e;
  for (int j = 0; j <= 256; ++j)
    for (int i = 0; i <= 256; ++i) {
      const double gx = static_cast<double>(gx0) + 0.5 * i, gy = static_cast<double>(gy0) + 0.5 * j;
      double ax = 0, ay = 0, ex = 0, ey = 0;
      const bool a = g.source(gx, gy, ax, ay), x = g.exact_source(gx, gy, ex, ey);
      EXPECT_EQ(a, x);
      if (!(a && x)) continue;
      e.x = std::max(e.x, std::abs(ax - ex));
      e.y = std::max(e.y, std::abs(ay - ey));
    }
  return e;
}

void expect_small_errors(const char* file) {
  const std::string path = dem_path(file);
  SKYLIT_REQUIRE(testing::missing_file(path));
  const HeightField dem = read_dem(path).field;
  const TileWindowSource source(dem);
  const MercatorToDem exact(dem);
  for (int z = 8; z <= 15; ++z) {
    const WarpSettings ws = source.warp_settings(z);
    const NodeGrid g(exact, z, 256, ws.node_spacing, 0, 0, 0, 0);  // nodes computed on demand
    double worst = 0;
    // The DEM's four corners (its poleward ones curve most) and its centre.
    for (const auto& [px, py] : {std::pair{0.0, 0.0}, {dem.width * 1.0, 0.0}, {0.0, dem.height * 1.0},
                                 {dem.width * 1.0, dem.height * 1.0}, {dem.width / 2.0, dem.height / 2.0}}) {
      double gx = 0, gy = 0;
      global_of(g, px, py, gx, gy);
      const Errors e = patch_errors(g, std::llround(gx) - 64, std::llround(gy) - 64);
      worst = std::max({worst, e.x, e.y});
    }
    std::printf("%s z %d: node spacing %d px, bound %.2e, measured max error %.2e source px\n", file, z,
                ws.node_spacing, ws.node_error_bound_px, worst);
    EXPECT_LE(ws.node_error_bound_px, kNodeTolerancePx) << "z " << z;
    // The bound is N²/8 · (M_xx + M_yy) from a sampled curvature: the measured error must
    // stay under it (10 % for the sample missing the maximum between its points).
    EXPECT_LE(worst, 1.1 * ws.node_error_bound_px + 1e-9) << "z " << z;
    EXPECT_LT(worst, 0.01) << "z " << z;
  }
}

TEST(ZoomTransform, UtmErrorIsWithinTheBound) { expect_small_errors("big_tujunga_srtm30_utm11n.tif"); }
TEST(ZoomTransform, GeographicErrorIsWithinTheBound) { expect_small_errors("cascades_skykomish_srtm1_4326.tif"); }
TEST(ZoomTransform, FineTransverseMercatorErrorIsWithinTheBound) {
  expect_small_errors("slovenia_lidar1m_d96tm.tif");  // 1 m pixels: the most source pixels per Mercator metre
}

// The same global point through grids cached for different windows: the same bits.
TEST(ZoomTransform, WindowsAgreeBitForBit) {
  const std::string path = dem_path("big_tujunga_srtm30_utm11n.tif");
  SKYLIT_REQUIRE(testing::missing_file(path));
  const HeightField dem = read_dem(path).field;
  const MercatorToDem exact(dem);
  const long long gx = 1407 * 256 + 37, gy = 3263 * 256 + 11;  // z 13, inside the DEM
  const NodeGrid a(exact, 13, 256, 32, gx - 300, gy - 300, gx + 10, gy + 10);
  const NodeGrid b(exact, 13, 256, 32, gx - 5, gy - 7, gx + 500, gy + 200);
  const NodeGrid none(exact, 13, 256, 32, 0, 0, 0, 0);  // every node on demand
  for (double d : {0.0, 0.5, 3.25, 17.5}) {
    double ax = 0, ay = 0, bx = 0, by = 0, nx = 0, ny = 0;
    ASSERT_TRUE(a.source(gx + d, gy + d, ax, ay));
    ASSERT_TRUE(b.source(gx + d, gy + d, bx, by));
    ASSERT_TRUE(none.source(gx + d, gy + d, nx, ny));
    EXPECT_EQ(ax, bx);
    EXPECT_EQ(ay, by);
    EXPECT_EQ(ax, nx);
    EXPECT_EQ(ay, ny);
  }
  // The batch the warper calls gives the single-point bits.
  std::vector<double> x, y;
  for (int k = 0; k < 100; ++k) {
    x.push_back(0.5 + k * 0.75);
    y.push_back(0.5 + (k / 10) * 3.0);
  }
  std::vector<double> bx(x), by(y);
  std::vector<int> ok(x.size());
  a.sources(x.size(), bx.data(), by.data(), ok.data(), double(gx), double(gy));
  for (std::size_t k = 0; k < x.size(); ++k) {
    double sx = 0, sy = 0;
    ASSERT_TRUE(ok[k]);
    ASSERT_TRUE(a.source(gx + x[k], gy + y[k], sx, sy));
    EXPECT_EQ(bx[k], sx);
    EXPECT_EQ(by[k], sy);
  }
  // At a node the approximation is the exact transform.
  double ax = 0, ay = 0, ex = 0, ey = 0;
  ASSERT_TRUE(a.source(1407 * 256, 3263 * 256, ax, ay));
  ASSERT_TRUE(a.exact_source(1407 * 256, 3263 * 256, ex, ey));
  EXPECT_EQ(ax, ex);
  EXPECT_EQ(ay, ey);
}

}  // namespace
}  // namespace skylit::terrain
