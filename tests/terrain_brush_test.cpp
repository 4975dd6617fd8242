// Terrain brush: checked against the falloff's analytic volume and values, the geometry
// of the disc, the 3×3 mean, and the change tracking the GPU upload relies on.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "terrain/brush.h"

namespace skylit::terrain {
namespace {

// The falloff as the header specifies it, written out independently of the code.
double falloff(double r, double R) { return r < R ? std::pow(1 - (r / R) * (r / R), 2) : 0.0; }

double dist(const HeightField& f, int i, int j, double x, double y) {
  return std::hypot(i * f.dx(j) - x, -j * f.dy - y);
}

HeightField noisy(int w, int h, double spacing, unsigned seed, double sigma = 1.0) {
  HeightField f(w, h, spacing);
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, sigma);
  for (float& v : f.heights) v = static_cast<float>(100 + n(rng));
  return f;
}

// Bounding box of the texels that differ between two fields of one size.
PixelRect diff_box(const HeightField& a, const HeightField& b) {
  PixelRect box;
  for (int j = 0; j < a.height; ++j)
    for (int i = 0; i < a.width; ++i)
      if (a.at(i, j) != b.at(i, j)) box = bounding_union(box, {i, j, 1, 1});
  return box;
}

TEST(TerrainBrush, RaiseVolumeIsTheFalloffIntegral) {
  // ∫ (1 − r²/R²)² dA over the disc = π R² / 3; a 0.25 m grid under R = 40 m.
  HeightField f(400, 400, 0.25);
  const double R = 40, s = 2.0;
  apply_brush(f, {BrushMode::Raise, R, s}, 50.0, -50.0);
  double volume = 0;
  for (float v : f.heights) volume += v * f.dx(0) * f.dy;
  EXPECT_NEAR(volume, std::numbers::pi * R * R * s / 3, 1e-4 * volume) << volume;
}

TEST(TerrainBrush, RaiseFollowsTheFalloffAndStopsAtTheRadius) {
  HeightField f = noisy(120, 100, 1.5, 1);
  const HeightField before = f;
  const double R = 30, s = 3.0, x = 60 * 1.5, y = -50 * 1.5;  // centred on texel (60, 50)
  apply_brush(f, {BrushMode::Raise, R, s}, x, y);
  EXPECT_FLOAT_EQ(f.at(60, 50), before.at(60, 50) + 3.0f);  // peak = strength
  int outside = 0;
  for (int j = 0; j < f.height; ++j)
    for (int i = 0; i < f.width; ++i) {
      const double r = dist(f, i, j, x, y);
      if (r >= R) {
        ++outside;
        ASSERT_EQ(f.at(i, j), before.at(i, j)) << i << "," << j;
      } else {
        ASSERT_NEAR(f.at(i, j) - before.at(i, j), s * falloff(r, R), 2e-5) << i << "," << j;
      }
    }
  EXPECT_GT(outside, 0);
}

TEST(TerrainBrush, DirtyRectIsExactlyTheChangedTexelsAndRevisionBumpsOnce) {
  HeightField f(50, 50, 1.0);
  const HeightField before = f;
  const auto rev = f.revision;
  // R = 10 on texel (25, 25): texels with i² + j² < 100, so offsets −9 … 9 (10 is on the rim).
  const PixelRect r = apply_brush(f, {BrushMode::Raise, 10.0, 1.0}, 25.0, -25.0);
  EXPECT_EQ(r, (PixelRect{16, 16, 19, 19}));
  EXPECT_EQ(r, diff_box(before, f));
  EXPECT_EQ(f.last_dirty, r);
  EXPECT_EQ(f.revision, rev + 1);
}

TEST(TerrainBrush, NoChangeNoRevision) {
  HeightField f(30, 30, 1.0);
  for (float& v : f.heights) v = 1000.0f;
  const auto rev = f.revision;
  const PixelRect dirty = f.last_dirty;
  EXPECT_TRUE(apply_brush(f, {BrushMode::Raise, 5.0, 0.0}, 15, -15).empty());
  EXPECT_TRUE(apply_brush(f, {BrushMode::Raise, 5.0, 1e-9}, 15, -15).empty());  // below float's step
  EXPECT_TRUE(apply_brush(f, {BrushMode::Smooth, 5.0, 1.0}, 15, -15).empty());  // flat already
  EXPECT_TRUE(apply_brush(f, {BrushMode::Lower, 5.0, 1.0}, 500, 500).empty());  // off the field
  EXPECT_EQ(f.revision, rev);
  EXPECT_EQ(f.last_dirty, dirty);
}

TEST(TerrainBrush, LowerIsTheNegativeOfRaise) {
  const HeightField base = noisy(80, 80, 2.0, 2);
  HeightField up = base, down = base;
  const PixelRect ru = apply_brush(up, {BrushMode::Raise, 50.0, 4.0}, 70, -90);
  const PixelRect rd = apply_brush(down, {BrushMode::Lower, 50.0, 4.0}, 70, -90);
  EXPECT_EQ(ru, rd);
  for (std::size_t k = 0; k < base.size(); ++k)
    ASSERT_NEAR(up.heights[k] - base.heights[k], base.heights[k] - down.heights[k], 2e-5) << k;
}

TEST(TerrainBrush, RowSpacingComesFromDxPerRow) {
  // Geographic-like field: east–west spacing shrinks northwards (row 0 is north).
  HeightField f(60, 40, 2.0);
  for (int j = 0; j < f.height; ++j) f.dx_per_row[j] = 1.0 + 0.05 * j;
  const HeightField before = f;
  const double R = 15, x = 20, y = -40;
  apply_brush(f, {BrushMode::Raise, R, 1.0}, x, y);
  for (int j = 0; j < f.height; ++j)
    for (int i = 0; i < f.width; ++i)
      ASSERT_NEAR(f.at(i, j) - before.at(i, j), falloff(dist(f, i, j, x, y), R), 1e-6) << i << "," << j;
}

TEST(TerrainBrush, SmoothKeepsAPlane) {
  // Also at the field's edges and next to nodata (whose stored height is garbage).
  HeightField f(64, 48, 1.0);
  f.dy = 2.0;
  for (int j = 0; j < f.height; ++j)
    for (int i = 0; i < f.width; ++i) f.at(i, j) = static_cast<float>(500 + 0.3 * i * f.dx(j) - 0.7 * j * f.dy);
  f.valid[20 * f.width + 30] = 0;
  f.at(30, 20) = 1e6f;
  const HeightField before = f;
  apply_brush(f, {BrushMode::Smooth, 200.0, 1.0}, 32, -48);  // covers everything
  const double ulp = std::nextafter(512.0f, 1024.0f) - 512.0f;  // heights are in [256, 1024)
  for (std::size_t k = 0; k < f.size(); ++k) ASSERT_NEAR(f.heights[k], before.heights[k], 2 * ulp) << k;
}

TEST(TerrainBrush, SmoothIsTheThreeByThreeMean) {
  // A spike of 9 on zeros: its 3×3 mean is 1, its neighbours' means are 1 as well, and
  // texels two away do not see it.
  HeightField f(21, 21, 1.0);
  f.at(10, 10) = 9;
  const double R = 100;
  apply_brush(f, {BrushMode::Smooth, R, 1.0}, 10, -10);
  EXPECT_FLOAT_EQ(f.at(10, 10), 1.0f);
  EXPECT_NEAR(f.at(11, 10), falloff(1, R), 1e-6);
  EXPECT_NEAR(f.at(9, 9), falloff(std::sqrt(2.0), R), 1e-6);
  EXPECT_EQ(f.at(12, 10), 0.0f);
  EXPECT_EQ(f.at(10, 8), 0.0f);
}

TEST(TerrainBrush, SmoothDoesNotDependOnTraversalOrder) {
  // Mirroring the input east–west (about the brush centre) mirrors the output: an
  // in-place, row-by-row smooth would drag already-smoothed values one way only.
  const HeightField f = noisy(41, 31, 1.0, 5);
  HeightField a = f, b = f;
  for (int j = 0; j < f.height; ++j)
    for (int i = 0; i < f.width; ++i) b.at(i, j) = f.at(f.width - 1 - i, j);
  apply_brush(a, {BrushMode::Smooth, 12.0, 1.0}, 20, -15);
  apply_brush(b, {BrushMode::Smooth, 12.0, 1.0}, 20, -15);
  for (int j = 0; j < f.height; ++j)
    for (int i = 0; i < f.width; ++i) ASSERT_NEAR(a.at(i, j), b.at(f.width - 1 - i, j), 2e-5) << i << "," << j;
}

TEST(TerrainBrush, SmoothReducesTheVarianceOfNoise) {
  // White noise, blend a toward the 3×3 mean: var = (1 − a)² + (2a − a²)/9 of the original.
  // Inside r < R/2, a = w(r) ≥ 0.5625, so var ≤ 0.281 (a little above with sampling noise).
  HeightField f = noisy(128, 128, 1.0, 3, 2.0);
  const HeightField before = f;
  const double R = 50, x = 64, y = -64;
  apply_brush(f, {BrushMode::Smooth, R, 1.0}, x, y);
  const auto variance = [&](const HeightField& g) {
    double s = 0, s2 = 0;
    int n = 0;
    for (int j = 0; j < g.height; ++j)
      for (int i = 0; i < g.width; ++i)
        if (dist(g, i, j, x, y) < R / 2) s += g.at(i, j), s2 += double(g.at(i, j)) * g.at(i, j), ++n;
    return s2 / n - (s / n) * (s / n);
  };
  const double ratio = variance(f) / variance(before);
  EXPECT_LT(ratio, 0.30);
  EXPECT_GT(ratio, 1.0 / 9 - 0.02);  // no stronger than a full 3×3 mean
}

TEST(TerrainBrush, ClipsAtTheEdges) {
  HeightField f(40, 30, 1.0);
  const double R = 20, x = -5, y = 5;  // centre off the north-west corner
  const PixelRect r = apply_brush(f, {BrushMode::Raise, R, 1.0}, x, y);
  EXPECT_EQ(r.x0, 0);
  EXPECT_EQ(r.y0, 0);
  EXPECT_NEAR(f.at(0, 0), falloff(std::hypot(5, 5), R), 1e-6);
  EXPECT_EQ(f.at(15, 0), 0.0f);  // r = hypot(20, 5) ≥ 20
  EXPECT_GT(f.at(14, 0), 0.0f);  // r = hypot(19, 5) < 20
  // South-east corner too, and a brush larger than the whole field.
  EXPECT_NO_THROW(apply_brush(f, {BrushMode::Smooth, 10.0, 1.0}, 39, -29));
  EXPECT_EQ(apply_brush(f, {BrushMode::Lower, 1e4, 1.0}, 20, -15), f.bounds());
}

TEST(TerrainBrush, NodataIsUntouched) {
  HeightField f = noisy(40, 40, 1.0, 4);
  for (int i = 15; i < 25; ++i) f.valid[20 * f.width + i] = 0;
  const HeightField before = f;
  for (BrushMode m : {BrushMode::Raise, BrushMode::Lower, BrushMode::Smooth}) {
    apply_brush(f, {m, 15.0, 1.0}, 20, -20);
    for (int i = 15; i < 25; ++i) ASSERT_EQ(f.at(i, 20), before.at(i, 20)) << i;
  }
}

TEST(TerrainBrush, BadInputThrowsOneLineAndChangesNothing) {
  HeightField f(20, 20, 1.0);
  const HeightField before = f;
  const auto rev = f.revision;
  const double inf = INFINITY, nan = NAN;
  const struct {
    Brush b;
    double x, y;
  } bad[] = {
      {{BrushMode::Raise, 0.0, 1.0}, 10, -10},     {{BrushMode::Raise, -3.0, 1.0}, 10, -10},
      {{BrushMode::Raise, nan, 1.0}, 10, -10},     {{BrushMode::Lower, inf, 1.0}, 10, -10},
      {{BrushMode::Raise, 5.0, nan}, 10, -10},     {{BrushMode::Raise, 5.0, inf}, 10, -10},
      {{BrushMode::Raise, 5.0, 1.0}, nan, -10},    {{BrushMode::Smooth, 5.0, 0.5}, 10, -inf},
      {{BrushMode::Smooth, 5.0, 1.5}, 10, -10},    {{BrushMode::Smooth, 5.0, -0.1}, 10, -10},
      {{BrushMode::Raise, 5.0, -1.0}, 10, -10},    {{BrushMode::Raise, 5.0, 1e300}, 10, -10},  // float overflow
  };
  for (const auto& c : bad) {
    try {
      apply_brush(f, c.b, c.x, c.y);
      ADD_FAILURE() << "no error for radius " << c.b.radius_m << " strength " << c.b.strength;
    } catch (const EditError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.rfind("apply_brush: ", 0), 0u) << msg;
      EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    }
  }
  EXPECT_EQ(f.revision, rev);
  EXPECT_EQ(f.heights, before.heights);
}

// The stamps a stroke along a straight line must make: its start, then every `spacing`.
HeightField stamped(HeightField f, const Brush& b, double x0, double y0, double x1, double y1, double spacing) {
  apply_brush(f, b, x0, y0);
  const double length = std::hypot(x1 - x0, y1 - y0), ux = (x1 - x0) / length, uy = (y1 - y0) / length;
  for (int k = 1; k * spacing <= length; ++k) apply_brush(f, b, x0 + k * spacing * ux, y0 + k * spacing * uy);
  return f;
}

double max_abs_diff(const HeightField& a, const HeightField& b) {
  double worst = 0;
  for (std::size_t k = 0; k < a.size(); ++k) worst = std::max(worst, std::abs(double(a.heights[k]) - b.heights[k]));
  return worst;
}

TEST(TerrainBrushStroke, IsItsStampsEverySpacingInOneRevisionPerMove) {
  const HeightField base = noisy(200, 120, 2.0, 5);
  const Brush b{BrushMode::Raise, 20.0, 1.5};
  const double spacing = 5.0, x0 = 40, y0 = -60, x1 = 40 + 0.8 * 52.5, y1 = -60 - 0.6 * 52.5;  // 10.5 spacings
  HeightField f = base;
  BrushStroke stroke(b, spacing);
  stroke.begin(f, x0, y0);
  const auto rev = f.revision;
  const HeightField before_move = f;
  const PixelRect r = stroke.move_to(f, x1, y1);
  EXPECT_EQ(stroke.stamps(), 11);
  EXPECT_EQ(f.revision, rev + 1);
  EXPECT_EQ(r, diff_box(before_move, f));
  EXPECT_EQ(f.last_dirty, r);
  EXPECT_LT(max_abs_diff(f, stamped(base, b, x0, y0, x1, y1, spacing)), 1e-5);
}

TEST(TerrainBrushStroke, ALineSampledOftenGivesWhatOneMoveGives) {
  const HeightField base = noisy(160, 160, 1.0, 6);
  const Brush b{BrushMode::Lower, 12.0, 0.7};
  HeightField once = base, often = base;
  BrushStroke a(b, 3.0), c(b, 3.0);
  a.begin(once, 30, -30);
  a.move_to(once, 130, -110);
  c.begin(often, 30, -30);
  for (int k = 1; k <= 37; ++k) c.move_to(often, 30 + 100.0 * k / 37, -30 - 80.0 * k / 37);
  EXPECT_EQ(a.stamps(), c.stamps());
  EXPECT_LT(max_abs_diff(once, often), 1e-4);
  EXPECT_GT(max_abs_diff(once, base), 1.0);
}

TEST(TerrainBrushStroke, ShortMovesCarryOverAndHoldingStillDoesNothing) {
  HeightField f = noisy(100, 100, 1.0, 7);
  const Brush b{BrushMode::Raise, 10.0, 1.0};
  const HeightField base = f;
  BrushStroke stroke(b, 4.0);
  stroke.begin(f, 50, -50);
  const auto rev = f.revision;
  EXPECT_TRUE(stroke.move_to(f, 50, -50).empty());     // held still
  EXPECT_TRUE(stroke.move_to(f, 52.4, -50).empty());   // 0.6 spacing
  EXPECT_EQ(f.revision, rev);
  EXPECT_FALSE(stroke.move_to(f, 54.8, -50).empty());  // 1.2: one stamp, at 54
  EXPECT_EQ(stroke.stamps(), 2);
  HeightField want = base;
  apply_brush(want, b, 50, -50);
  apply_brush(want, b, 54, -50);
  EXPECT_LT(max_abs_diff(f, want), 1e-5);
}

TEST(TerrainBrushStroke, AnOverflowMidStrokeKeepsWhatWasAppliedTracked) {
  HeightField f(100, 20, 1.0);
  for (int j = 0; j < f.height; ++j)
    for (int i = 50; i < f.width; ++i) f.at(i, j) = 3e38f;  // the right half near float's top
  BrushStroke stroke({BrushMode::Raise, 5.0, 1e38}, 2.0);
  stroke.begin(f, 10, -10);
  const HeightField before = f;
  const auto rev = f.revision;
  EXPECT_THROW(stroke.move_to(f, 90, -10), EditError);
  EXPECT_EQ(f.revision, rev + 1);
  EXPECT_GT(stroke.stamps(), 10);
  const PixelRect changed = diff_box(before, f);
  const PixelRect& d = f.last_dirty;
  EXPECT_TRUE(changed.x0 >= d.x0 && changed.y0 >= d.y0 && changed.x1() <= d.x1() && changed.y1() <= d.y1());
  EXPECT_LT(changed.x1(), 50 + 5);  // nothing past the first stamp that overflows
}

TEST(TerrainBrushStroke, BadSpacingThrows) {
  for (double s : {0.0, -1.0, double(NAN), double(INFINITY)})
    EXPECT_THROW(BrushStroke({BrushMode::Raise, 5.0, 1.0}, s), EditError) << s;
}

}  // namespace
}  // namespace skylit::terrain
