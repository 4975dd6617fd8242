// Poses from synthetic tracks with closed-form answers: a circle flown at constant speed
// banks atan(v²/(g·R)) (coordinated turn); a straight climb pitches atan(v_z/v_h); a
// gap has no pose; standing still keeps the last heading with no bank.
#include "flight/track_sampler.h"

#include <gtest/gtest.h>

#include <cmath>

namespace skylit::flight {
namespace {

constexpr double kG = 9.80665;
constexpr double kDeg = 180.0 / M_PI;

// Fixes every second on a clockwise (right-hand) circle of radius r around the origin
// at speed v, climbing at vz.
std::vector<PlacedFix> circle(double r, double v, double vz, int seconds) {
  std::vector<PlacedFix> f;
  for (int k = 0; k <= seconds; ++k) {
    const double a = v / r * k;  // angle flown, clockwise from north of the centre
    f.push_back({100.0 + k, {r * std::sin(a), r * std::cos(a), 2500.0 + vz * k}});
  }
  return f;
}

TEST(TrackSampler, CircleBanksAsACoordinatedTurn) {
  const double r = 100.0, v = 25.0;
  const TrackSampler s(circle(r, v, 0.0, 120));
  const double expected = std::atan(v * v / (kG * r)) * kDeg;  // 32.5°
  for (double t : {130.0, 150.5, 171.25}) {
    const auto p = s.pose_at(t);
    ASSERT_TRUE(p) << t;
    EXPECT_NEAR(p->attitude.bank_deg, expected, 0.2) << t;
    EXPECT_NEAR(p->attitude.pitch_deg, 0.0, 1e-9) << t;
    // Heading: the tangent of a clockwise circle is 90° right of the bearing from the centre.
    const double bearing = std::atan2(p->position.x, p->position.y) * kDeg;
    const double d = std::remainder(p->attitude.heading_deg - (bearing + 90.0), 360.0);
    EXPECT_NEAR(d, 0.0, 0.5) << t;
  }
  // The mirror circle (anticlockwise) banks left.
  auto left = circle(r, v, 0.0, 60);
  for (auto& f : left) f.position.x = -f.position.x;
  EXPECT_NEAR(TrackSampler(left).pose_at(130.0)->attitude.bank_deg, -expected, 0.2);
}

TEST(TrackSampler, StraightClimbPitchesAtTheFlightPathAngle) {
  std::vector<PlacedFix> f;
  const double vh = 30.0, vz = 3.0, course = 60.0 / kDeg;
  for (int k = 0; k <= 20; ++k) f.push_back({double(k), {vh * k * std::sin(course), vh * k * std::cos(course), 1000 + vz * k}});
  const TrackSampler s(f);
  const auto p = s.pose_at(10.5);
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->attitude.pitch_deg, std::atan(vz / vh) * kDeg, 1e-9);  // 5.711°
  EXPECT_NEAR(p->attitude.heading_deg, 60.0, 1e-9);
  EXPECT_NEAR(p->attitude.bank_deg, 0.0, 1e-9);
  EXPECT_NEAR(p->position.z, 1000 + vz * 10.5, 1e-9);
  EXPECT_NEAR(p->position.x, vh * 10.5 * std::sin(course), 1e-9);
  // The window clips at the ends: still the same climb.
  EXPECT_NEAR(s.pose_at(0.0)->attitude.pitch_deg, std::atan(vz / vh) * kDeg, 1e-9);
  EXPECT_FALSE(s.pose_at(-0.5));
  EXPECT_FALSE(s.pose_at(20.5));
}

TEST(TrackSampler, NoPoseInsideAGapAndStillKeepsTheHeading) {
  std::vector<PlacedFix> f = {{0, {0, 0, 500}}, {1, {10, 0, 500}}, {2, {20, 0, 500}},   // east
                              {3, {20, 0, 500}}, {4, {20, 0, 500}}, {5, {20, 0, 500}},  // standing
                              {30, {400, 0, 500}}, {31, {410, 0, 500}}};              // after a 25 s gap
  const TrackSampler s(f);
  EXPECT_TRUE(s.pose_at(2.0));
  EXPECT_FALSE(s.pose_at(10.0));
  EXPECT_FALSE(s.position_at(29.9));
  EXPECT_TRUE(s.pose_at(30.5));
  const auto still = s.pose_at(5.0);
  ASSERT_TRUE(still);
  EXPECT_NEAR(still->attitude.heading_deg, 90.0, 1e-9);
  EXPECT_EQ(still->attitude.bank_deg, 0.0);
  EXPECT_EQ(still->attitude.pitch_deg, 0.0);
  // A shorter gap threshold splits the track earlier.
  SamplerOptions o;
  o.max_gap_s = 0.5;
  EXPECT_FALSE(TrackSampler(f, o).pose_at(0.5));
}

TEST(TrackSampler, InvalidFixesAreNeverPlacedAndGapsAreFoundAroundThem) {
  Track t;
  for (int k = 0; k < 40; ++k) {
    Fix f;
    f.time_s = k;
    f.lat_deg = 0.001 * k;
    f.valid = k < 10 || k >= 30;  // a 20 s V stretch
    f.stated = Altitude{100.0, AltitudeDatum::geoid_msl};
    t.fixes.push_back(f);
  }
  const TrackSampler s(t, [](double lon, double lat) { return glm::dvec2(lon * 1e5, lat * 1e5); },
                       [](const Fix& f, double, double) { return std::optional<double>(f.stated->metres); });
  EXPECT_EQ(s.fixes().size(), 20u);
  EXPECT_FALSE(s.pose_at(20.0));
  const auto gaps = find_gaps(t);
  ASSERT_EQ(gaps.size(), 1u);
  EXPECT_DOUBLE_EQ(gaps[0].start_s, 9.0);
  EXPECT_DOUBLE_EQ(gaps[0].length_s, 21.0);
}

}  // namespace
}  // namespace skylit::flight
