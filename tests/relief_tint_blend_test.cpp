// The tint blends against hand-computed values: the W3C soft-light formula, multiply at a weight.
#include "shading/relief/tint_blend.h"

#include <gtest/gtest.h>

namespace {

using namespace skylit::relief;

TEST(ReliefTintBlend, SoftLightAtHandPoints) {
  for (const double c : {0.0, 0.1, 0.3, 0.7, 1.0}) EXPECT_DOUBLE_EQ(soft_light(c, 0.5), c);  // 0.5 leaves it
  EXPECT_DOUBLE_EQ(soft_light(0.5, 0.0), 0.25);  // 0.5 − 1·0.5·0.5
  EXPECT_DOUBLE_EQ(soft_light(0.2, 1.0), ((16 * 0.2 - 12) * 0.2 + 4) * 0.2);  // D(0.2) = 0.448
  EXPECT_NEAR(soft_light(0.2, 1.0), 0.448, 1e-12);
  EXPECT_DOUBLE_EQ(soft_light(0.64, 0.75), 0.64 + 0.5 * (0.8 - 0.64));  // sqrt(0.64) = 0.8
  EXPECT_DOUBLE_EQ(soft_light_mix(0.5, 0.0, 0.4), 0.4 * 0.25 + 0.6 * 0.5);
  EXPECT_DOUBLE_EQ(soft_light_mix(0.3, 0.9, 0.0), 0.3);
  // Multiply at opacity W: W = 1 is c·r, W = 0 leaves c.
  EXPECT_DOUBLE_EQ(multiply_mix(0.5, 0.2, 0.75), 0.5 * (0.25 + 0.75 * 0.2));
  EXPECT_DOUBLE_EQ(multiply_mix(0.6, 0.5, 1.0), 0.3);
  EXPECT_DOUBLE_EQ(multiply_mix(0.6, 0.1, 0.0), 0.6);
}

}  // namespace
