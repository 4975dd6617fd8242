// Flight trails: the track → polyline conversion on the CPU (gaps break it, the colour
// ramps' ends at the track's extremes, climb rates by finite differences).
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <vector>

#include "view/trail_polyline.h"

namespace skylit::view {
namespace {

// The ramps' published stops (matplotlib's viridis, ColorBrewer's RdBu), as the spec.
glm::vec3 hex(int h) { return glm::vec3((h >> 16) & 0xff, (h >> 8) & 0xff, h & 0xff) / 255.0f; }
const glm::vec3 kViridisLow = hex(0x440154), kViridisQuarter = hex(0x3b528b), kViridisMiddle = hex(0x21918c),
                kViridisHigh = hex(0xfde725);
const glm::vec3 kSinkEnd = hex(0x0571b0), kSinkHalf = hex(0x92c5de), kLevel = hex(0xf7f7f7),
                kClimbHalf = hex(0xf4a582), kClimbEnd = hex(0xca0020);

void expect_colour(const glm::vec3& got, const glm::vec3& want, const char* what) {
  EXPECT_LT(glm::distance(got, want), 1e-6f) << what << ": got (" << got.r << ", " << got.g << ", " << got.b << ")";
}

glm::dvec3 same(const glm::dvec3& p) { return p; }

// Fixes at these times, at position(t).
template <class Position>
std::vector<flight::PlacedFix> fixes_at(const std::vector<double>& times, Position position) {
  std::vector<flight::PlacedFix> out;
  for (double t : times) out.push_back({t, position(t)});
  return out;
}

TEST(TrailPolylines, AGapBreaksTheLineAndShorterStepsDoNot) {
  // 1 s steps, a 16 s step (a gap: over kDefaultMaxGapSeconds = 15), a 14 s step (none).
  std::vector<double> times;
  for (int k = 0; k < 10; ++k) times.push_back(k);
  for (int k = 25; k <= 30; ++k) times.push_back(k);
  for (int k = 44; k <= 48; ++k) times.push_back(k);
  const auto fixes = fixes_at(times, [](double t) { return glm::dvec3(100.0 * t, 50.0, 1000.0 + t); });
  const glm::dvec3 shift(-1000.0, 200.0, 0.0);
  const auto trail = trail_polylines(fixes, [&](const glm::dvec3& p) { return p + shift; }, TrailColour::Altitude);
  ASSERT_EQ(trail.size(), 2u);
  ASSERT_EQ(trail[0].vertices.size(), 10u);
  ASSERT_EQ(trail[1].vertices.size(), 11u);
  std::size_t k = 0;
  for (const TrailPolyline& p : trail)
    for (const TrailVertex& v : p.vertices) {
      EXPECT_EQ(v.time_s, fixes[k].time_s);
      EXPECT_EQ(v.position, fixes[k].position + shift) << "through the caller's field-frame mapping";
      ++k;
    }
  EXPECT_EQ(trail[0].vertices.back().time_s, 9.0);
  EXPECT_EQ(trail[1].vertices.front().time_s, 25.0);
  // A tighter threshold finds the 14 s step too.
  EXPECT_EQ(trail_polylines(fixes, same, TrailColour::Altitude, 10.0).size(), 3u);
}

TEST(TrailPolylines, AFixAloneBetweenGapsMakesNoLine) {
  const auto fixes = fixes_at({0, 1, 2, 30, 60, 61}, [](double t) { return glm::dvec3(t, 0.0, 100.0); });
  const auto trail = trail_polylines(fixes, same, TrailColour::Altitude);
  ASSERT_EQ(trail.size(), 2u);
  EXPECT_EQ(trail[0].vertices.size(), 3u);
  EXPECT_EQ(trail[1].vertices.front().time_s, 60.0);
}

TEST(TrailPolylines, AltitudeExtremesAreTheRampEnds) {
  const std::vector<double> z{700, 500, 900, 600, 1300, 800};  // 700: a quarter of 500..1300
  std::vector<flight::PlacedFix> fixes;
  for (std::size_t k = 0; k < z.size(); ++k) fixes.push_back({double(k), {10.0 * k, 0.0, z[k]}});
  const auto trail = trail_polylines(fixes, same, TrailColour::Altitude);
  ASSERT_EQ(trail.size(), 1u);
  const auto& v = trail[0].vertices;
  EXPECT_EQ(v[1].value, 500.0);
  expect_colour(v[1].colour, kViridisLow, "lowest fix");
  expect_colour(v[4].colour, kViridisHigh, "highest fix");
  expect_colour(v[0].colour, kViridisQuarter, "a quarter up");
}

TEST(TrailPolylines, ConstantClimbFromFiniteDifferencesOnUnevenSteps) {
  const std::vector<double> times{0, 1, 3, 4, 8, 9, 10, 14};
  for (const auto& [rate, want] : {std::pair{2.5, kClimbHalf}, std::pair{-2.5, kSinkHalf}, std::pair{8.0, kClimbEnd},
                                  std::pair{-8.0, kSinkEnd}}) {
    const auto fixes = fixes_at(times, [r = rate](double t) { return glm::dvec3(20.0 * t, 0.0, 200.0 + r * t); });
    const auto trail = trail_polylines(fixes, same, TrailColour::ClimbRate);
    ASSERT_EQ(trail.size(), 1u);
    for (const TrailVertex& v : trail[0].vertices) {
      EXPECT_NEAR(v.value, rate, 1e-9) << "at t = " << v.time_s;
      expect_colour(v.colour, want, "climb rate on the RdBu ramp (clamped at +-5 m/s)");
    }
  }
}

TEST(TrailPolylines, ClimbIsNotDifferencedAcrossAGap) {
  // Level at 100 m, a 55 s gap, level at 900 m: a chord would read 14.5 m/s.
  const auto fixes = fixes_at({0, 1, 2, 3, 4, 5, 60, 61, 62, 63, 64, 65},
                              [](double t) { return glm::dvec3(t, 0.0, t < 30.0 ? 100.0 : 900.0); });
  const auto trail = trail_polylines(fixes, same, TrailColour::ClimbRate);
  ASSERT_EQ(trail.size(), 2u);
  for (const TrailPolyline& p : trail)
    for (const TrailVertex& v : p.vertices) {
      EXPECT_EQ(v.value, 0.0) << "at t = " << v.time_s;
      expect_colour(v.colour, kLevel, "level flight");
    }
}

}  // namespace
}  // namespace skylit::view
