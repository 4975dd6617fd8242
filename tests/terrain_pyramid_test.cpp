// Height pyramid: level sizes, reproduction of constants and linear functions, the
// filter's frequency response against its Fourier transform, interpolation, and
// staleness tracking with partial updates.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "terrain/analytic_scenes.h"
#include "terrain/editing.h"
#include "terrain/pyramid.h"

namespace skylit::terrain {
namespace {

HeightField ramp_field(int w, int h, double a, double bx, double by) {
  HeightField f(w, h, 10.0);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) f.at(i, j) = static_cast<float>(a + bx * i + by * j);
  return f;
}

TEST(TerrainPyramid, LevelSizesFollowTheLevelStep) {
  const HeightField f(512, 384, 30.0);
  for (int k_v : {1, 2, 4}) {
    PyramidOptions o;
    o.k_v = k_v;
    const HeightPyramid p(f, o);
    ASSERT_GT(p.levels(), 2);
    for (int l = 0; l < p.levels(); ++l) {
      const auto& lv = p.level(l);
      const double s = std::pow(2.0, static_cast<double>(l) / k_v);
      EXPECT_EQ(lv.width, std::max(1L, std::lround(512 / s))) << "level " << l;
      EXPECT_EQ(lv.height, std::max(1L, std::lround(384 / s))) << "level " << l;
      EXPECT_DOUBLE_EQ(lv.step_x, 512.0 / lv.width);
      EXPECT_NEAR(lv.step_x, s, 0.5 * s * s / 384 + 1e-12);  // rounding only
      EXPECT_NEAR(lv.dy, lv.step_y * 30.0, 1e-9);
      EXPECT_NEAR(lv.dx(0), lv.step_x * 30.0, 1e-9);
    }
    // Automatic count: the coarsest level keeps ≥ 2 texels on its short side, one more would not.
    const int last = p.levels() - 1;
    EXPECT_GE(std::min(p.level(last).width, p.level(last).height), 2);
    EXPECT_LT(std::lround(384 / std::pow(2.0, static_cast<double>(last + 1) / k_v)), 2);
  }
}

TEST(TerrainPyramid, ConstantStaysConstant) {
  const HeightField f = flat_plane(97, 61, 25.0, 1234.5);
  const HeightPyramid p(f);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-5, 100);
  for (int l = 0; l < p.levels(); ++l) {
    for (float v : p.level(l).samples) ASSERT_NEAR(v, 1234.5f, 2e-3) << "level " << l;
    for (int t = 0; t < 20; ++t) {
      const double x = u(rng), y = u(rng);
      EXPECT_NEAR(p.sample(l, x, y, Interpolation::CubicBSpline), 1234.5f, 2e-3);
      EXPECT_NEAR(p.sample(l, x, y, Interpolation::Bilinear), 1234.5f, 2e-3);
    }
  }
}

// B-splines reproduce linear functions: the prefiltered level samples of a ramp are
// the ramp at the level's texel centres (away from the clamped edges).
TEST(TerrainPyramid, LinearRampIsReproduced) {
  const double a = 500, bx = 0.75, by = -0.4;
  const HeightField f = ramp_field(200, 150, a, bx, by);
  PyramidOptions o;
  o.k_v = 4;
  o.levels = 14;  // up to step 2^(13/4) ≈ 9.5
  const HeightPyramid p(f, o);
  for (int l = 1; l < p.levels(); ++l) {
    const auto& lv = p.level(l);
    const double margin_x = 2 * lv.step_x + 2, margin_y = 2 * lv.step_y + 2;
    int checked = 0;
    for (int j = 0; j < lv.height; ++j)
      for (int i = 0; i < lv.width; ++i) {
        const double x0 = (i + 0.5) * lv.step_x - 0.5, y0 = (j + 0.5) * lv.step_y - 0.5;  // texel-centre rule
        if (x0 < margin_x || y0 < margin_y || x0 > 199 - margin_x || y0 > 149 - margin_y) continue;
        ASSERT_NEAR(lv.sample_at(i, j), a + bx * x0 + by * y0, 2e-3) << "level " << l << " texel " << i << "," << j;
        ++checked;
      }
    EXPECT_GT(checked, 0) << "level " << l;
    // Continuous sampling in level-0 coordinates reproduces it too, away from the
    // edges: the clamped samples (2s + 2) and the spline's edge condition (its effect
    // decays by 2 − √3 per texel: 8 texels).
    for (double x0 : {30.3, 77.7, 120.05})
      for (double y0 : {31.9, 64.5, 100.2}) {
        const double mx = (margin_x + 8 * lv.step_x), my = (margin_y + 8 * lv.step_y);
        if (x0 < mx || y0 < my || x0 > 199 - mx || y0 > 149 - my) continue;
        EXPECT_NEAR(p.sample(l, x0, y0, Interpolation::CubicBSpline), a + bx * x0 + by * y0, 3e-3);
        EXPECT_NEAR(p.sample(l, x0, y0, Interpolation::Bilinear), a + bx * x0 + by * y0, 3e-3);
      }
  }
}

// Frequency response: a sinusoid cos(ωx) comes out scaled by the Fourier transform of
// the kernel, sinc²(ω/2) (linear interpolation) × sinc⁴(sω/2) (B-spline of width s),
// with sinc(t) = sin t / t.
TEST(TerrainPyramid, FilterResponseMatchesFourierTransform) {
  const int w = 400, h = 8;
  const double omega = 2 * M_PI / 37.0;
  HeightField f(w, h, 1.0);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) f.at(i, j) = static_cast<float>(std::cos(omega * i));
  PyramidOptions o;
  o.k_v = 4;
  o.levels = 8;
  const HeightPyramid p(f, o);
  auto sinc = [](double t) { return t == 0 ? 1.0 : std::sin(t) / t; };
  for (int l = 1; l < p.levels(); ++l) {
    const auto& lv = p.level(l);
    const double s = lv.step_x;
    const double gain = std::pow(sinc(omega / 2), 2) * std::pow(sinc(s * omega / 2), 4);
    for (int i = 0; i < lv.width; ++i) {
      const double x0 = (i + 0.5) * s - 0.5;
      if (x0 < 2 * s + 2 || x0 > w - 3 - 2 * s) continue;
      // The field is constant in y: any row will do.
      ASSERT_NEAR(lv.sample_at(i, lv.height / 2), gain * std::cos(omega * x0), 2e-4)
          << "level " << l << " (s = " << s << ")";
    }
  }
}

TEST(TerrainPyramid, BSplineInterpolatesTheSamples) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0, 1000);
  HeightField f(23, 17, 5.0);
  for (auto& z : f.heights) z = u(rng);
  const HeightPyramid p(f);
  for (int l = 0; l < p.levels(); ++l) {
    const auto& lv = p.level(l);
    for (int j = 0; j < lv.height; ++j)
      for (int i = 0; i < lv.width; ++i) {
        ASSERT_NEAR(sample_bspline(lv, i, j), lv.sample_at(i, j), 2e-3) << l;
        ASSERT_NEAR(sample_bilinear(lv, i, j), lv.sample_at(i, j), 1e-3) << l;
      }
    // Clamp-to-edge: outside the grid the edge value continues.
    EXPECT_NEAR(sample_bspline(lv, -3.0, 0.0), lv.sample_at(0, 0), 2e-3);
    EXPECT_NEAR(sample_bilinear(lv, lv.width + 5.0, lv.height - 1.0), lv.sample_at(lv.width - 1, lv.height - 1), 1e-3);
    EXPECT_TRUE(std::isfinite(sample_bspline(lv, NAN, 1.0)));
  }
  // Between samples the cubic B-spline is smooth: it is the exact tensor spline; check
  // one point by direct evaluation of Σ c β3 with the stored coefficients.
  const auto& lv0 = p.level(0);
  const double x = 7.3, y = 4.6;
  auto b3 = [](double t) {
    t = std::abs(t);
    return t < 1 ? (4 - 6 * t * t + 3 * t * t * t) / 6 : t < 2 ? (2 - t) * (2 - t) * (2 - t) / 6 : 0.0;
  };
  double direct = 0;
  for (int j = 0; j < lv0.height; ++j)
    for (int i = 0; i < lv0.width; ++i) direct += lv0.coeffs[j * lv0.width + i] * b3(x - i) * b3(y - j);
  EXPECT_NEAR(sample_bspline(lv0, x, y), direct, 1e-3);
}

TEST(TerrainPyramid, GeographicRowsKeepTheirSpacing) {
  HeightField f(64, 64, 30.0);
  for (int j = 0; j < 64; ++j) f.dx_per_row[j] = 20.0 + 0.1 * j;  // shrinking toward the north
  PyramidOptions o;
  o.levels = 5;
  const HeightPyramid p(f, o);
  const auto& lv = p.level(4);  // step 2
  EXPECT_DOUBLE_EQ(lv.step_x, 2.0);
  EXPECT_NEAR(lv.dx(0), 2.0 * (20.0 + 0.1 * 0.5), 1e-9);  // level row 0 centre is level-0 row 0.5
}

TEST(TerrainPyramid, EditsMakeItStaleAndUpdateMatchesRebuild) {
  HeightField f = gaussian_hill(120, 90, 10.0, 300.0, 150.0);
  PyramidOptions o;
  o.k_v = 3;
  HeightPyramid p(f, o);
  EXPECT_FALSE(p.is_stale(f));
  EXPECT_FALSE(p.update(f));

  std::vector<float> block(6 * 4, 900.0f);
  replace_heights(f, {40, 30, 6, 4}, block);
  EXPECT_TRUE(p.is_stale(f));
  EXPECT_TRUE(p.update(f));  // one edit: partial update
  EXPECT_FALSE(p.is_stale(f));
  const HeightPyramid fresh(f, o);
  ASSERT_EQ(fresh.levels(), p.levels());
  for (int l = 0; l < p.levels(); ++l) {
    for (std::size_t k = 0; k < fresh.level(l).samples.size(); ++k)
      ASSERT_NEAR(p.level(l).samples[k], fresh.level(l).samples[k], 1e-3) << "level " << l;
    for (std::size_t k = 0; k < fresh.level(l).coeffs.size(); ++k)
      ASSERT_NEAR(p.level(l).coeffs[k], fresh.level(l).coeffs[k], 1e-3) << "level " << l;
  }

  // Two edits since the last update: the pyramid cannot know the first rectangle and
  // must rebuild.
  replace_heights(f, {0, 0, 2, 2}, std::vector<float>(4, -50.0f));
  replace_heights(f, {100, 80, 3, 3}, std::vector<float>(9, 42.0f));
  EXPECT_TRUE(p.update(f));
  const HeightPyramid fresh2(f, o);
  for (int l = 0; l < p.levels(); ++l)
    for (std::size_t k = 0; k < fresh2.level(l).samples.size(); ++k)
      ASSERT_NEAR(p.level(l).samples[k], fresh2.level(l).samples[k], 1e-3);
  EXPECT_EQ(p.source_revision(), f.revision);
}

TEST(TerrainPyramid, RejectsBadOptions) {
  const HeightField f(8, 8, 1.0);
  PyramidOptions o;
  o.k_v = 0;
  EXPECT_THROW(HeightPyramid(f, o), std::invalid_argument);
  o.k_v = 4;
  o.levels = -1;
  EXPECT_THROW(HeightPyramid(f, o), std::invalid_argument);
}

}  // namespace
}  // namespace skylit::terrain
