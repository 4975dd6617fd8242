// Flight trails: the track → polyline conversion on the CPU (gaps break it, the colour
// ramps' ends at the track's extremes, climb rates by finite differences), and the drawn
// lines where the camera's matrices put them, broken at a gap, cut at the playback time
// and depth-tested. llvmpipe where there is no GPU.
#include "gpu_test_util.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "view/camera.h"
#include "view/offscreen_target.h"
#include "view/trail_draw.h"
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

// ---- Drawn ----

using TrailDrawTest = gpu::testing::GpuTest;

constexpr int kSize = 256;
constexpr double kExaggeration = 2.0;

// From 450 m over the origin, looking north and 19 degrees off straight down.
glm::dmat4 test_view_proj() {
  const CameraPose pose{{0.0, 0.0, 450.0}, glm::normalize(glm::dvec3(0, 0.35, -1)), glm::normalize(glm::dvec3(0, 1, 0.35))};
  return projection_matrix({50.0, 1.0, 1.0, 5000.0}) * view_matrix(pose);
}

struct Projected {
  glm::dvec2 pixel;  // x right, y down (read_rgb's rows, top first)
  double depth;      // window depth, 0..1
};

// Where the GL pipeline should put a field-frame point: clip, NDC, viewport.
Projected project(const glm::dvec3& p) {
  const glm::dvec4 clip = test_view_proj() * glm::dvec4(p.x, p.y, p.z * kExaggeration, 1.0);
  const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
  return {{(ndc.x + 1.0) * 0.5 * kSize, (1.0 - ndc.y) * 0.5 * kSize}, ndc.z * 0.5 + 0.5};
}

using Image = std::vector<std::uint8_t>;

Image draw(std::span<const TrailPolyline> trail, double drawn_until_s, double clear_depth = 1.0,
           double width_px = kTrailWidthPx, const CurvatureDrop& drop = {}) {
  OffscreenTarget target(kSize, kSize);
  target.bind();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClearDepth(clear_depth);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  TrailDraw trails(trail);
  trails.draw(test_view_proj(), kExaggeration, drop, drawn_until_s, width_px);
  glFinish();
  return target.read_rgb();
}

glm::vec3 at(const Image& img, int x, int y) {
  const std::size_t p = (static_cast<std::size_t>(y) * kSize + x) * 3;
  return glm::vec3(img[p], img[p + 1], img[p + 2]) / 255.0f;
}

// The drawn colour within `r` pixels of a point (a 1-pixel line's fragments may sit
// beside the exact projection), or nullopt where nothing was drawn there.
std::optional<glm::vec3> drawn_near(const Image& img, glm::dvec2 pixel, int r) {
  const int cx = static_cast<int>(std::floor(pixel.x)), cy = static_cast<int>(std::floor(pixel.y));
  for (int y = cy - r; y <= cy + r; ++y)
    for (int x = cx - r; x <= cx + r; ++x) {
      if (x < 0 || y < 0 || x >= kSize || y >= kSize) continue;
      if (at(img, x, y) != glm::vec3(0.0f)) return at(img, x, y);
    }
  return std::nullopt;
}

bool inside(glm::dvec2 p) { return p.x > 3 && p.y > 3 && p.x < kSize - 3 && p.y < kSize - 3; }

// Track A (west, x = -40): 1 s fixes from y = 0 to 90, a 61 s gap, then 10 s fixes from
// y = 150 to 250. Track B (east, x = +40): 1 s fixes with no gap. Both level at 50 m.
std::vector<flight::PlacedFix> track_a() {
  std::vector<flight::PlacedFix> f;
  for (int t = 0; t < 10; ++t) f.push_back({double(t), {-40.0, 10.0 * t, 50.0}});
  for (int t = 70; t <= 90; t += 10) f.push_back({double(t), {-40.0, 150.0 + 5.0 * (t - 70), 50.0}});
  return f;
}
std::vector<flight::PlacedFix> track_b() {
  std::vector<flight::PlacedFix> f;
  for (int t = 0; t < 80; ++t) f.push_back({double(t), {40.0, 3.0 * t, 50.0}});
  return f;
}

TEST_F(TrailDrawTest, FallsWithTheCurvedGround) {
  // A level track at 50 m (100 m exaggerated) across the view, x = −100 … 100 at y = 200,
  // under a drop of d^2 / 500 m from the eye's (0, 0): drawn where z · exaggeration − drop
  // projects, 80 to 100 m lower, and not where the undropped track would be.
  std::vector<flight::PlacedFix> fixes;
  for (int t = 0; t <= 20; ++t) fixes.push_back({double(t), {-100.0 + 10.0 * t, 200.0, 50.0}});
  const std::vector<TrailPolyline> trail = trail_polylines(fixes, same, TrailColour::Altitude);
  const CurvatureDrop drop{1.0 / 500.0, {0.0, 0.0}};
  const Image img = draw(trail, 1e12, 1.0, kTrailWidthPx, drop);
  int checked = 0;
  for (const flight::PlacedFix& f : fixes) {
    const glm::dvec3 p = f.position;
    const Projected fallen = project({p.x, p.y, p.z - drop.at(p.x, p.y) / kExaggeration});
    const Projected level = project(p);
    if (!inside(fallen.pixel) || !inside(level.pixel)) continue;
    if (glm::distance(fallen.pixel, level.pixel) < 4.0) continue;  // near the eye: too little to tell
    EXPECT_TRUE(drawn_near(img, fallen.pixel, 1)) << "x = " << p.x;
    EXPECT_FALSE(drawn_near(img, level.pixel, 1)) << "x = " << p.x;
    ++checked;
  }
  EXPECT_GE(checked, 5);
}

TEST_F(TrailDrawTest, TwoTracksDrawnWhereTheCameraPutsThemWithTheGapLeftOpen) {
  std::vector<TrailPolyline> trail = trail_polylines(track_a(), same, TrailColour::Altitude);
  ASSERT_EQ(trail.size(), 2u);
  for (TrailPolyline& p : trail_polylines(track_b(), same, TrailColour::ClimbRate)) trail.push_back(std::move(p));
  const Image img = draw(trail, 1e12);
  for (const TrailPolyline& p : trail)
    for (std::size_t k = 0; k + 1 < p.vertices.size(); ++k) {
      const glm::dvec3 mid = 0.5 * (p.vertices[k].position + p.vertices[k + 1].position);
      const Projected q = project(mid);
      ASSERT_TRUE(inside(q.pixel)) << "the test's camera sees the whole trail";
      const auto c = drawn_near(img, q.pixel, 1);
      ASSERT_TRUE(c.has_value()) << "segment at y = " << mid.y << ", x = " << mid.x << ", pixel " << q.pixel.x << ", "
                                 << q.pixel.y;
      EXPECT_LT(glm::distance(*c, p.vertices[k].colour), 1.5f / 255.0f) << "its vertices' colour";
    }
  // Level flight: A (by altitude, no range) in the ramp's middle, B (by climb) level white.
  EXPECT_LT(glm::distance(*drawn_near(img, project({-40.0, 50.0, 50.0}).pixel, 1), kViridisMiddle), 1.5f / 255.0f);
  EXPECT_LT(glm::distance(*drawn_near(img, project({40.0, 50.0, 50.0}).pixel, 1), kLevel), 1.5f / 255.0f);

  const Projected before = project({-40.0, 90.0, 50.0}), after = project({-40.0, 150.0, 50.0});
  ASSERT_GT(glm::distance(before.pixel, after.pixel), 10.0) << "a gap long enough on screen to see";
  EXPECT_FALSE(drawn_near(img, project({-40.0, 120.0, 50.0}).pixel, 2)) << "the gap's middle is not bridged";
  EXPECT_TRUE(drawn_near(img, project({40.0, 120.0, 50.0}).pixel, 1)) << "track B has no gap there";
}

TEST_F(TrailDrawTest, DrawnUpToThePlaybackTimeInsideASegment) {
  const std::vector<TrailPolyline> trail = trail_polylines(track_a(), same, TrailColour::Altitude);
  // Cut at 85 s: halfway along the segment from (y = 200, 80 s) to (y = 250, 90 s).
  const Image img = draw(trail, 85.0);
  for (double y : {10.0, 80.0, 160.0, 195.0, 210.0, 217.0})
    EXPECT_TRUE(drawn_near(img, project({-40.0, y, 50.0}).pixel, 1)) << "drawn before the cut, y = " << y;
  for (double y : {233.0, 240.0, 248.0})
    EXPECT_FALSE(drawn_near(img, project({-40.0, y, 50.0}).pixel, 1)) << "not after it, y = " << y;
  ASSERT_GT(glm::distance(project({-40.0, 217.0, 50.0}).pixel, project({-40.0, 233.0, 50.0}).pixel), 3.0);

  const Image none = draw(trail, -1.0);
  EXPECT_EQ(std::count(none.begin(), none.end(), 0), static_cast<std::ptrdiff_t>(none.size()))
      << "nothing before the first fix";
}

TEST_F(TrailDrawTest, DepthTestedAgainstWhatIsAlreadyDrawn) {
  const std::vector<TrailPolyline> trail = trail_polylines(track_a(), same, TrailColour::Altitude);
  // Depth as if a surface lay at the depth of the point y = 45: nearer parts pass.
  const Image img = draw(trail, 1e12, project({-40.0, 45.0, 50.0}).depth);
  for (double y : {5.0, 20.0, 35.0}) EXPECT_TRUE(drawn_near(img, project({-40.0, y, 50.0}).pixel, 1)) << "y = " << y;
  for (double y : {60.0, 80.0, 200.0})
    EXPECT_FALSE(drawn_near(img, project({-40.0, y, 50.0}).pixel, 1)) << "hidden, y = " << y;
}

// Drawn pixels along image row y.
int lit_in_row(const Image& img, int y) {
  int n = 0;
  for (int x = 0; x < kSize; ++x) n += at(img, x, y) != glm::vec3(0.0f);
  return n;
}

TEST_F(TrailDrawTest, AsWideAsAskedAcrossTheSegment) {
  // Track B alone runs north, up the screen: a row crosses it nearly square.
  const std::vector<TrailPolyline> trail = trail_polylines(track_b(), same, TrailColour::ClimbRate);
  for (double width : {1.0, 3.0, 6.0}) {
    const Image img = draw(trail, 1e12, 1.0, width);
    const int y = static_cast<int>(project({40.0, 120.0, 50.0}).pixel.y);
    EXPECT_NEAR(lit_in_row(img, y), width, 1.0) << "width " << width;
  }
}

TEST_F(TrailDrawTest, ASegmentFromBehindTheEyeIsDrawnInFrontOfIt) {
  // Ends 500 m south-west of the eye, behind it (10 m below, as drawn ×2) or on its plane
  // (175 m below: w = 0, no projection at all), to 200 m ahead, 50 m up.
  for (const double z_behind : {220.0, 137.5}) {
    const glm::dvec3 behind{-300.0, -500.0, z_behind}, ahead{40.0, 200.0, 25.0};
    const std::vector<flight::PlacedFix> fixes = {{0.0, behind}, {1.0, ahead}};
    const std::vector<TrailPolyline> trail = trail_polylines(fixes, same, TrailColour::Altitude);
    ASSERT_EQ(trail.size(), 1u);
    const Image img = draw(trail, 1e12);
    for (double t : {0.8, 0.9, 1.0}) {
      const Projected q = project(glm::mix(behind, ahead, t));
      ASSERT_TRUE(inside(q.pixel)) << t;
      EXPECT_TRUE(drawn_near(img, q.pixel, 1)) << "z " << z_behind << ", t = " << t;
      if (t < 1.0) {  // at its width: the end behind the eye moved in front of it, not projected
        EXPECT_NEAR(lit_in_row(img, static_cast<int>(q.pixel.y)), kTrailWidthPx, 1.0) << "z " << z_behind << ", t = " << t;
      }
    }
  }
}

}  // namespace
}  // namespace skylit::view
