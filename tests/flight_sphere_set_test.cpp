// Sphere sets: placement against rotations derived by hand, the JSON round trip, and
// one-line errors for bad files.
#include "flight/sphere_set.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace skylit::flight {
namespace {

void expect_near(const glm::dvec3& a, const glm::dvec3& b) {
  EXPECT_NEAR(a.x, b.x, 1e-12);
  EXPECT_NEAR(a.y, b.y, 1e-12);
  EXPECT_NEAR(a.z, b.z, 1e-12);
}

// 1 m ahead, 2 m to the left and 3 m above the reference point, radii 0.5, 0.6, 0.7.
SphereSet axes_set() {
  SphereSet s;
  s.name = "axes";
  s.spheres = {{{1, 0, 0}, 0.5}, {{0, 2, 0}, 0.6}, {{0, 0, 3}, 0.7}};
  return s;
}

TEST(Place, LevelHeadingEast) {
  // Nose east: forward = east, left = north, up = up.
  const auto p = place(axes_set(), {0.0, {100, 200, 300}, {90, 0, 0}});
  ASSERT_EQ(p.size(), 3u);
  expect_near(p[0].centre, {101, 200, 300});
  expect_near(p[1].centre, {100, 202, 300});
  expect_near(p[2].centre, {100, 200, 303});
  EXPECT_EQ(p[2].radius, 0.7);
}

TEST(Place, ClimbingEastPitchesForwardUpAndUpBackward) {
  // Pitch 30° about the (northward) left axis: forward (cos 30, 0, sin 30), up (−sin 30, 0, cos 30).
  const auto p = place(axes_set(), {0.0, {100, 200, 300}, {90, 30, 0}});
  const double c = std::sqrt(3.0) / 2.0;
  expect_near(p[0].centre, {100 + c, 200, 300.5});
  expect_near(p[1].centre, {100, 202, 300});
  expect_near(p[2].centre, {100 - 1.5, 200, 300 + 3 * c});
}

TEST(Place, BankedRightHeadingNorthRaisesTheLeftWing) {
  // Bank 30° right about the northward forward axis: left (−cos 30, 0, sin 30), up (sin 30, 0, cos 30).
  const auto p = place(axes_set(), {0.0, {0, 0, 0}, {0, 0, 30}});
  const double c = std::sqrt(3.0) / 2.0;
  expect_near(p[0].centre, {0, 1, 0});
  expect_near(p[1].centre, {-2 * c, 0, 1});
  expect_near(p[2].centre, {1.5, 0, 3 * c});
}

TEST(SphereSetJson, RoundTrips) {
  SphereSet s = axes_set();
  s.span_m = 15;
  s.length_m = 6.5;
  s.source = "test";
  s.has_fit_error = true;
  s.fit_error.volume_error = 0.25;
  s.fit_error.solid_angle_rays = 1000;
  const SphereSet back = parse_sphere_set(sphere_set_json(s), "mem");
  EXPECT_EQ(back.name, "axes");
  ASSERT_EQ(back.spheres.size(), 3u);
  expect_near(back.spheres[1].centre, {0, 2, 0});
  EXPECT_EQ(back.spheres[2].radius, 0.7);
  EXPECT_EQ(back.span_m, 15);
  EXPECT_EQ(back.source, "test");
  EXPECT_TRUE(back.has_fit_error);
  EXPECT_EQ(back.fit_error.volume_error, 0.25);
  EXPECT_EQ(back.fit_error.solid_angle_rays, 1000);
}

std::string error_of(const std::string& text) {
  try {
    parse_sphere_set(text, "set.json");
  } catch (const SphereSetError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    return e.what();
  }
  return "";
}

TEST(SphereSetJson, BadFilesGiveOneClearLine) {
  EXPECT_NE(error_of("{").find("set.json: not valid JSON"), std::string::npos);
  EXPECT_EQ(error_of("[]"), "set.json: not a JSON object");
  EXPECT_EQ(error_of(R"({"spheres": []})"), "set.json: missing \"name\" (a string)");
  EXPECT_EQ(error_of(R"({"name": "a"})"), "set.json: missing \"spheres\" (an array)");
  EXPECT_EQ(error_of(R"({"name": "a", "spheres": []})"), "set.json: \"spheres\" is empty");
  EXPECT_EQ(error_of(R"({"name": "a", "spheres": [{"centre": [0, 0], "radius": 1}]})"),
            "set.json: sphere 0: missing \"centre\" ([x, y, z])");
  EXPECT_EQ(error_of(R"({"name": "a", "spheres": [{"centre": [0, 0, 0]}]})"), "set.json: sphere 0: missing \"radius\"");
  EXPECT_NE(error_of(R"({"name": "a", "spheres": [{"centre": [0, 0, 0], "radius": 0}]})").find("is not positive"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"name": "a", "spheres": [{"centre": [0, 0, 0], "radius": -2}]})").find("is not positive"),
            std::string::npos);
  // JSON has no NaN or infinity; a number beyond double is refused by the parser.
  EXPECT_NE(error_of(R"({"name": "a", "spheres": [{"centre": [0, 1e999, 0], "radius": 1}]})").find("1e999"),
            std::string::npos);
  EXPECT_EQ(error_of(R"({"name": "a", "spheres": [{"centre": [0, "x", 0], "radius": 1}]})"),
            "set.json: sphere 0 centre is not a number");
  std::string many = R"({"name": "a", "spheres": [)";
  for (std::size_t i = 0; i <= kMaxSpheres; ++i) many += std::string(i ? "," : "") + R"({"centre":[0,0,0],"radius":1})";
  many += "]}";
  EXPECT_NE(error_of(many).find("100001 spheres, more than the 100000 allowed"), std::string::npos);
  EXPECT_THROW(read_sphere_set("/nonexistent/set.json"), SphereSetError);
}

}  // namespace
}  // namespace skylit::flight
