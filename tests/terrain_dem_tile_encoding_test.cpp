// Terrain-RGB and Terrarium codes (terrain/dem_tile_encoding.h): known codes worked
// out by hand from the published formulas, round trips within half a step, clamping,
// and the nodata (alpha 0) policy.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "terrain/dem_tile_encoding.h"

namespace skylit::terrain {
namespace {

TEST(DemTileEncoding, KnownTerrainRgbCodes) {
  // 0 m: (0 + 10000) / 0.1 = 100000 = 1·65536 + 134·256 + 160.
  EXPECT_EQ(encode_height(DemEncoding::TerrainRgb, 0.0), (Rgb{1, 134, 160}));
  EXPECT_DOUBLE_EQ(decode_height(DemEncoding::TerrainRgb, {1, 134, 160}), 0.0);
  // 8848.86 m: 188488.6 → 188489 = 2·65536 + 224·256 + 73, which decodes to 8848.9 m.
  EXPECT_EQ(encode_height(DemEncoding::TerrainRgb, 8848.86), (Rgb{2, 224, 73}));
  EXPECT_NEAR(decode_height(DemEncoding::TerrainRgb, {2, 224, 73}), 8848.9, 1e-9);
  // −10000 m is code 0.
  EXPECT_EQ(encode_height(DemEncoding::TerrainRgb, -10000.0), (Rgb{0, 0, 0}));
}

TEST(DemTileEncoding, KnownTerrariumCodes) {
  // (128, 0, 0): 128·256 + 0 + 0/256 − 32768 = 0 m.
  EXPECT_EQ(encode_height(DemEncoding::Terrarium, 0.0), (Rgb{128, 0, 0}));
  EXPECT_DOUBLE_EQ(decode_height(DemEncoding::Terrarium, {128, 0, 0}), 0.0);
  // 1000.5 m: 33768.5 = 131·256 + 232 + 128/256.
  EXPECT_EQ(encode_height(DemEncoding::Terrarium, 1000.5), (Rgb{131, 232, 128}));
  EXPECT_DOUBLE_EQ(decode_height(DemEncoding::Terrarium, {131, 232, 128}), 1000.5);
  // −11 m (Nice's lowest pixel): 32757 = 127·256 + 245.
  EXPECT_EQ(encode_height(DemEncoding::Terrarium, -11.0), (Rgb{127, 245, 0}));
  // (0, 0, 0) is −32768 m, the reason nodata does not use it.
  EXPECT_DOUBLE_EQ(decode_height(DemEncoding::Terrarium, {0, 0, 0}), -32768.0);
}

TEST(DemTileEncoding, RoundTripWithinHalfAStep) {
  for (DemEncoding e : {DemEncoding::TerrainRgb, DemEncoding::Terrarium}) {
    const double step = encoding_params(e).step();
    double worst = 0;
    for (int k = -40000; k <= 900000; ++k) {
      const double h = k * 0.0137;  // −548 … 12330 m, off the step grid
      worst = std::max(worst, std::abs(decode_height(e, encode_height(e, h)) - h));
    }
    EXPECT_LE(worst, step / 2 + 1e-9) << encoding_name(e);
    EXPECT_GT(worst, step / 2 * 0.9) << encoding_name(e);  // and it does use the half step
    // Float heights as the renderer stores them round-trip the same way.
    const float f = 1234.567f;
    EXPECT_LE(std::abs(decode_height(e, encode_height(e, f)) - f), step / 2 + 1e-9);
  }
  // Nearest, ties upward (Terrarium steps are exact binary fractions).
  const double s = 1.0 / 256;
  EXPECT_DOUBLE_EQ(decode_height(DemEncoding::Terrarium, encode_height(DemEncoding::Terrarium, 5 + 0.49 * s)), 5.0);
  EXPECT_DOUBLE_EQ(decode_height(DemEncoding::Terrarium, encode_height(DemEncoding::Terrarium, 5 + 0.5 * s)), 5 + s);
  EXPECT_DOUBLE_EQ(decode_height(DemEncoding::Terrarium, encode_height(DemEncoding::Terrarium, -5 - 0.51 * s)), -5 - s);
}

TEST(DemTileEncoding, OutOfRangeHeightsClamp) {
  const Rgb top{255, 255, 255}, bottom{0, 0, 0};
  EXPECT_EQ(encode_height(DemEncoding::TerrainRgb, -10994.0), bottom);  // Challenger Deep: below −10 km
  EXPECT_EQ(encode_height(DemEncoding::TerrainRgb, 2e6), top);
  EXPECT_DOUBLE_EQ(decode_height(DemEncoding::TerrainRgb, top), 1667721.5);  // −10000 + 16777215 · 0.1
  EXPECT_EQ(encode_height(DemEncoding::Terrarium, -40000.0), bottom);
  EXPECT_EQ(encode_height(DemEncoding::Terrarium, 40000.0), top);
  EXPECT_DOUBLE_EQ(decode_height(DemEncoding::Terrarium, top), 32767.0 + 255.0 / 256);
  EXPECT_DOUBLE_EQ(encoding_params(DemEncoding::Terrarium).max_height(), 32767.0 + 255.0 / 256);
  EXPECT_DOUBLE_EQ(encoding_params(DemEncoding::TerrainRgb).min_height(), -10000.0);
  EXPECT_EQ(encode_height(DemEncoding::Terrarium, std::numeric_limits<double>::infinity()), top);
  EXPECT_EQ(encode_height(DemEncoding::Terrarium, std::numeric_limits<double>::quiet_NaN()), (Rgb{128, 0, 0}));
}

TEST(DemTileEncoding, TileKeepsFilledHeightsUnderAlphaZero) {
  HeightField f(3, 2, 10.0);
  f.heights = {0.0f, 100.0f, 200.0f, 300.0f, 123.4f, 500.0f};
  f.valid = {1, 1, 1, 1, 0, 1};  // (1, 1) is a void, filled with 123.4 m
  std::vector<std::uint8_t> rgba(2 * 2 * 4, 7);
  encode_dem_tile(DemEncoding::Terrarium, f, {1, 0, 2, 2}, rgba);  // columns 1…2
  auto px = [&](int k) { return Rgb{rgba[4 * k], rgba[4 * k + 1], rgba[4 * k + 2]}; };
  EXPECT_EQ(px(0), encode_height(DemEncoding::Terrarium, 100.0));
  EXPECT_EQ(px(1), encode_height(DemEncoding::Terrarium, 200.0));
  EXPECT_EQ(px(2), encode_height(DemEncoding::Terrarium, 123.4f));  // the void keeps its fill
  EXPECT_EQ(px(3), encode_height(DemEncoding::Terrarium, 500.0));
  EXPECT_EQ(rgba[3], 255);
  EXPECT_EQ(rgba[7], 255);
  EXPECT_EQ(rgba[11], 0);
  EXPECT_EQ(rgba[15], 255);
  std::vector<std::uint8_t> small(15);
  EXPECT_THROW(encode_dem_tile(DemEncoding::Terrarium, f, {1, 0, 2, 2}, small), std::invalid_argument);
  EXPECT_THROW(encode_dem_tile(DemEncoding::Terrarium, f, {2, 0, 2, 2}, rgba), std::invalid_argument);
  EXPECT_THROW(encode_dem_tile(DemEncoding::Terrarium, f, {0, 0, 0, 2}, rgba), std::invalid_argument);
}

TEST(DemTileEncoding, Names) {
  EXPECT_EQ(encoding_name(DemEncoding::TerrainRgb), "mapbox");
  EXPECT_EQ(encoding_name(DemEncoding::Terrarium), "terrarium");
  EXPECT_EQ(parse_dem_encoding("mapbox"), DemEncoding::TerrainRgb);
  EXPECT_EQ(parse_dem_encoding("terrain-rgb"), DemEncoding::TerrainRgb);
  EXPECT_EQ(parse_dem_encoding("terrarium"), DemEncoding::Terrarium);
  EXPECT_FALSE(parse_dem_encoding("png").has_value());
}

}  // namespace
}  // namespace skylit::terrain
