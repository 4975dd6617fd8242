// coarsen_by_two (terrain/field_coarsening.h): a plane stays the plane at the coarse
// texels' centres (the mean of a 2×2 block of a linear function is its centre value),
// the spacing and geotransform double, nodata blocks stay nodata and a partly valid
// block averages its valid texels only.
#include "terrain/field_coarsening.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace {

using skylit::terrain::coarsen_by_two;
using skylit::terrain::HeightField;

TEST(Coarsening, PlaneStaysThePlaneAtBlockCentres) {
  HeightField f(9, 7, 2.0);  // odd sides: the last column and row are dropped
  for (int j = 0; j < f.height; ++j)
    for (int i = 0; i < f.width; ++i) f.at(i, j) = static_cast<float>(100.0 + 3.0 * i - 1.5 * j);
  f.georef.geotransform = {1000.0, 2.0, 0.0, 5000.0, 0.0, -2.0};
  const HeightField c = coarsen_by_two(f);
  ASSERT_EQ(c.width, 4);
  ASSERT_EQ(c.height, 3);
  EXPECT_DOUBLE_EQ(c.dy, 4.0);
  EXPECT_DOUBLE_EQ(c.dx(0), 4.0);
  EXPECT_DOUBLE_EQ(c.georef.geotransform[0], 1000.0);
  EXPECT_DOUBLE_EQ(c.georef.geotransform[1], 4.0);
  EXPECT_DOUBLE_EQ(c.georef.geotransform[5], -4.0);
  for (int J = 0; J < c.height; ++J)
    for (int I = 0; I < c.width; ++I) {
      const double ci = 2 * I + 0.5, cj = 2 * J + 0.5;  // the block's centre in source texels
      EXPECT_NEAR(c.at(I, J), 100.0 + 3.0 * ci - 1.5 * cj, 1e-4);
      EXPECT_TRUE(c.is_valid(I, J));
    }
  EXPECT_NE(c.id.value(), f.id.value());
}

TEST(Coarsening, NodataIsLeftOutOfTheMean) {
  HeightField f(4, 2, 1.0);
  const float v[] = {10, 20, 5, 5, 30, 40, 5, 5};
  for (int k = 0; k < 8; ++k) f.heights[k] = v[k];
  f.valid = {1, 0, 0, 0, 1, 0, 0, 0};  // block 0: 10 and 30 valid; block 1: none
  const HeightField c = coarsen_by_two(f);
  EXPECT_FLOAT_EQ(c.at(0, 0), 20.0f);
  EXPECT_TRUE(c.is_valid(0, 0));
  EXPECT_FALSE(c.is_valid(1, 0));
  EXPECT_FLOAT_EQ(c.at(1, 0), 5.0f);
}

TEST(Coarsening, TooSmallIsAnError) { EXPECT_THROW(coarsen_by_two(HeightField(1, 8, 1.0)), std::invalid_argument); }

}  // namespace
