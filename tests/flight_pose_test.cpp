#include "flight/pose.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>

namespace skylit::flight {
namespace {

void expect_near(const glm::dvec3& a, const glm::dvec3& b) {
  EXPECT_NEAR(a.x, b.x, 1e-12);
  EXPECT_NEAR(a.y, b.y, 1e-12);
  EXPECT_NEAR(a.z, b.z, 1e-12);
}

TEST(BodyToEnu, LevelNorthIsForwardNorthLeftWestUpUp) {
  const glm::dmat3 r = body_to_enu({});
  expect_near(r[0], {0, 1, 0});
  expect_near(r[1], {-1, 0, 0});
  expect_near(r[2], {0, 0, 1});
}

TEST(BodyToEnu, HeadingEastClimbingAndBankedRight) {
  expect_near(body_to_enu({90, 0, 0})[0], {1, 0, 0});
  const glm::dmat3 climb = body_to_enu({90, 30, 0});
  expect_near(climb[0], {std::cos(M_PI / 6), 0, 0.5});
  // Banked 90° right heading north: the left wing points straight up, the top east.
  const glm::dmat3 bank = body_to_enu({0, 0, 90});
  expect_near(bank[1], {0, 0, 1});
  expect_near(bank[2], {1, 0, 0});
}

TEST(BodyToEnu, IsARotation) {
  const glm::dmat3 r = body_to_enu({37, -12, 25});
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(glm::dot(r[i], r[j]), i == j ? 1.0 : 0.0, 1e-12);
  EXPECT_NEAR(glm::dot(glm::cross(r[0], r[1]), r[2]), 1.0, 1e-12);  // right-handed
}

}  // namespace
}  // namespace skylit::flight
