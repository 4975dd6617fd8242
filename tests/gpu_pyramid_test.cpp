// The height pyramid built on the GPU (gpu::GpuPyramid: shaders/pyramid_filter.comp,
// shaders/pyramid_coeffs.comp) against the CPU reference terrain::HeightPyramid: level
// count and geometry, the level table the march kernel reads, and every level's
// B-spline coefficients, for odd, even and non-square sizes, k_v = 1, 2, 4, on fields
// with a nodata void filled by Laplace inpainting (as the DEM reader fills them); and
// a pyramid larger than the storage-binding limit, each level bound as its own range;
// and the pyramid of samples that bilinear levels read (no solve).
//
// Tolerance: |Δc| ≤ kCoeffTol × the field's height range (hmax − hmin), every
// coefficient of every level. The GPU filters in float32 around the window's centre
// value (error ~ ε·relief·√taps) and solves the tridiagonal systems in float32
// (error ~ a few ε·|c|, |c| ≤ 3·max|h| since the inverse's ∞-norm is ≤ 3); the CPU does
// both in double and rounds to float. With heights of 2–3.4 km over a 1.4 km range,
// ε·3·3400 m / 1400 m ≈ 4e-7 per rounding; observed ≤ 1.6e-6 (printed).
// Runs on Mesa llvmpipe where there is no GPU.
#include "gpu_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "gpu/buffers.h"
#include "gpu/gpu_pyramid.h"
#include "terrain/nodata_fill.h"
#include "terrain/pyramid.h"
#include "terrain/synthetic.h"

namespace skylit::gpu {
namespace {

constexpr double kCoeffTol = 1e-5;

using GpuPyramidTest = testing::GpuTest;

// Synthetic mountains 2–3.4 km high (a high base: float rounding scales with it) with a
// rectangular void filled by Laplace inpainting.
terrain::HeightField void_filled_field(int w, int h, std::uint64_t seed) {
  terrain::SyntheticOptions o;
  o.width = w;
  o.height = h;
  o.spacing = 30.0;
  o.seed = seed;
  o.base_height = 2000.0;
  o.relief = 1400.0;
  o.feature_size = 1200.0;
  terrain::HeightField f = terrain::make_synthetic_terrain(o);
  for (int j = h / 3; j < h / 3 + std::max(1, h / 5); ++j)
    for (int i = w / 4; i < w / 4 + std::max(1, w / 6); ++i) f.valid[static_cast<std::size_t>(j) * w + i] = 0;
  terrain::fill_laplace(f.heights, f.valid, w, h);
  return f;
}

double height_range(const terrain::HeightField& f) {
  const auto [lo, hi] = std::minmax_element(f.heights.begin(), f.heights.end());
  return static_cast<double>(*hi) - *lo;
}

// Coefficients of all levels including the padding between them (the march's buffer texture).
std::size_t total_floats(const GpuPyramid& gpu) {
  const int last = gpu.levels() - 1;
  return gpu.offset(last) + static_cast<std::size_t>(gpu.shape(last).width) * gpu.shape(last).height;
}

// Builds both pyramids and compares them; returns the largest |Δc| / range.
double expect_pyramids_match(GpuPyramid& gpu, const terrain::HeightField& f, int k_v) {
  const terrain::PyramidOptions options{.k_v = k_v};
  const terrain::HeightPyramid cpu(f, options);
  const Buffer heights = Buffer::from(std::span<const float>(f.heights));
  gpu.build(heights, f.width, f.height, options);
  EXPECT_EQ(gpu.levels(), cpu.levels());
  const double range = height_range(f);
  double worst = 0.0;
  // Each level starts at the first multiple of the binding alignment after the previous one.
  const std::size_t align = storage_offset_alignment();
  std::size_t end = 0;
  for (int l = 0; l < std::min(gpu.levels(), cpu.levels()); ++l) {
    SCOPED_TRACE("level " + std::to_string(l));
    const terrain::PyramidLevel& lv = cpu.level(l);
    // The geometry the march's step table takes from it (gpu_pipeline.cpp).
    EXPECT_EQ(gpu.shape(l).width, lv.width);
    EXPECT_EQ(gpu.shape(l).height, lv.height);
    EXPECT_EQ(gpu.offset(l) * sizeof(float) % align, 0u);
    EXPECT_GE(gpu.offset(l), end);
    EXPECT_LT((gpu.offset(l) - end) * sizeof(float), align);
    EXPECT_EQ(gpu.shape(l).step_x, lv.step_x);
    EXPECT_EQ(gpu.shape(l).step_y, lv.step_y);
    end = gpu.offset(l) + lv.coeffs.size();
    const std::vector<float> c = gpu.download_level(l);
    if (c.size() != lv.coeffs.size()) {
      ADD_FAILURE() << "level sizes differ";
      continue;
    }
    double level_worst = 0.0;
    for (std::size_t k = 0; k < c.size(); ++k)
      level_worst = std::max(level_worst, std::abs(static_cast<double>(c[k]) - lv.coeffs[k]) / range);
    EXPECT_LE(level_worst, kCoeffTol) << lv.width << "×" << lv.height;
    worst = std::max(worst, level_worst);
  }
  return worst;
}

TEST_F(GpuPyramidTest, CoefficientsMatchTheCpuPyramid) {
  GpuPyramid gpu;
  struct Size {
    int w, h;
  };
  // Odd, even, non-square both ways, a narrow strip, and one whose coarse levels have
  // hundreds of taps per output.
  for (const Size s : {Size{67, 45}, Size{64, 64}, Size{40, 96}, Size{3, 50}, Size{257, 131}})
    for (int k_v : {1, 2, 4}) {
      SCOPED_TRACE(std::to_string(s.w) + "×" + std::to_string(s.h) + " k_v " + std::to_string(k_v));
      const terrain::HeightField f = void_filled_field(s.w, s.h, 11 + s.w);
      const double worst = expect_pyramids_match(gpu, f, k_v);
      std::cout << s.w << "×" << s.h << " k_v " << k_v << ": max |Δc| / range = " << worst << "\n";
    }
}

// Without coefficients (bilinear levels): every level holds the CPU pyramid's filtered
// samples, and the tracked maximum (the march's exit bound) is their largest.
TEST_F(GpuPyramidTest, SamplesWithoutCoefficientsMatchTheCpuPyramid) {
  GpuPyramid gpu;
  const terrain::HeightField f = void_filled_field(67, 45, 5);
  const terrain::PyramidOptions options{.k_v = 4};
  const terrain::HeightPyramid cpu(f, options);
  const Buffer heights = Buffer::from(std::span<const float>(f.heights));
  gpu.build(heights, f.width, f.height, options, false);
  ASSERT_EQ(gpu.levels(), cpu.levels());
  const double range = height_range(f);
  float top = -std::numeric_limits<float>::infinity();
  for (int l = 0; l < gpu.levels(); ++l) {
    const std::vector<float> v = gpu.download_level(l);
    const std::vector<float>& want = cpu.level(l).samples;
    ASSERT_EQ(v.size(), want.size()) << "level " << l;
    for (std::size_t k = 0; k < v.size(); ++k) {
      ASSERT_LE(std::abs(static_cast<double>(v[k]) - want[k]) / range, kCoeffTol) << "level " << l << " sample " << k;
      top = std::max(top, v[k]);
    }
  }
  EXPECT_EQ(gpu.max_coeff(), top);
  // Built again with coefficients, level 1 differs from its samples (the solve ran).
  gpu.build(heights, f.width, f.height, options, true);
  EXPECT_NE(gpu.download_level(1), cpu.level(1).samples);
}

TEST_F(GpuPyramidTest, ConstantFieldStaysConstantAtEveryLevel) {
  // Independent of the CPU code: the filter's weights sum to 1 and the interpolation
  // system's rows sum to 1, so every coefficient of a constant field is that constant.
  terrain::HeightField f(37, 23, 10.0);
  std::fill(f.heights.begin(), f.heights.end(), 1234.5f);
  GpuPyramid gpu;
  const Buffer heights = Buffer::from(std::span<const float>(f.heights));
  gpu.build(heights, f.width, f.height, terrain::PyramidOptions{.k_v = 2});
  for (int l = 0; l < gpu.levels(); ++l)
    for (float c : gpu.download_level(l)) ASSERT_NEAR(c, 1234.5, 1234.5 * 1e-6) << "level " << l;
}

TEST_F(GpuPyramidTest, TablesAreKeptForTheSameSize) {
  const terrain::HeightField a = void_filled_field(50, 30, 3), b = void_filled_field(50, 30, 4);
  GpuPyramid gpu;
  const terrain::PyramidOptions options{.k_v = 4};
  const Buffer ha = Buffer::from(std::span<const float>(a.heights));
  const Buffer hb = Buffer::from(std::span<const float>(b.heights));
  EXPECT_GT(gpu.build(ha, a.width, a.height, options), 0u);
  EXPECT_EQ(gpu.build(hb, b.width, b.height, options), 0u);  // same geometry: nothing uploaded
  const terrain::HeightPyramid cpu(b, options);
  for (int l = 0; l < gpu.levels(); ++l) {
    const std::vector<float> c = gpu.download_level(l);
    for (std::size_t k = 0; k < c.size(); ++k)
      ASSERT_NEAR(c[k], cpu.level(l).coeffs[k], kCoeffTol * height_range(b)) << "level " << l;
  }
  EXPECT_GT(gpu.build(ha, a.width, a.height, terrain::PyramidOptions{.k_v = 2}), 0u);  // new options: new tables
}

TEST_F(GpuPyramidTest, BuildsAPyramidLargerThanTheBindingLimit) {
  // The binding limit lowered to level 0's size: every level fits, all of them do not.
  const terrain::HeightField f = void_filled_field(67, 45, 5);
  const std::size_t limit = f.heights.size() * sizeof(float);
  GpuPyramid gpu(limit);
  const double worst = expect_pyramids_match(gpu, f, 4);
  EXPECT_GT(total_floats(gpu) * sizeof(float), 2 * limit);
  std::cout << "pyramid of " << total_floats(gpu) * sizeof(float) << " B under a " << limit
            << " B binding limit (offset alignment " << storage_offset_alignment()
            << " B): max |Δc| / range = " << worst << "\n";
}

TEST_F(GpuPyramidTest, ALevelOverTheBindingLimitThrows) {
  const terrain::HeightField f = void_filled_field(67, 45, 5);
  const std::size_t level0_bytes = f.heights.size() * sizeof(float);
  GpuPyramid gpu(level0_bytes - sizeof(float));  // one float short of level 0
  const Buffer heights = Buffer::from(std::span<const float>(f.heights));
  try {
    gpu.build(heights, f.width, f.height, terrain::PyramidOptions{.k_v = 4});
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    const std::string expected = "level 0 of the height pyramid needs " + std::to_string(level0_bytes) + " bytes";
    EXPECT_NE(what.find(expected), std::string::npos) << what;
    EXPECT_NE(what.find("GL_MAX_SHADER_STORAGE_BLOCK_SIZE"), std::string::npos) << what;
  }
}

// An edit's update (filters only where the taps read the edited texels) against a build
// of the edited field from scratch: bit for bit at every level, and the same maximum.
TEST_F(GpuPyramidTest, AnUpdateAfterEditsIsABuildOfTheEditedField) {
  struct Case {
    int w, h, k_v;
  };
  for (const Case c : {Case{67, 45, 4}, Case{67, 45, 1}, Case{257, 131, 4}, Case{3, 50, 2}})
    for (bool coefficients : {true, false}) {
      SCOPED_TRACE(std::to_string(c.w) + "×" + std::to_string(c.h) + " k_v " + std::to_string(c.k_v) +
                   (coefficients ? " coefficients" : " samples"));
      terrain::HeightField f = void_filled_field(c.w, c.h, 21 + c.w);
      const terrain::PyramidOptions options{.k_v = c.k_v};
      Buffer heights = Buffer::from(std::span<const float>(f.heights));
      GpuPyramid updated;
      updated.build(heights, f.width, f.height, options, coefficients, true);
      ASSERT_TRUE(updated.updatable());
      const std::vector<float> before = updated.download_level(std::min(1, updated.levels() - 1));
      // Inside, at a corner, a whole row, one texel: each edit on top of the last.
      const terrain::PixelRect edits[] = {{c.w / 3, c.h / 2, std::max(1, c.w / 5), std::max(1, c.h / 6)},
                                          {0, 0, 2, 3},
                                          {0, c.h - 1, c.w, 1},
                                          {c.w - 1, c.h / 3, 1, 1}};
      for (const terrain::PixelRect& e : edits) {
        for (int j = e.y0; j < e.y1(); ++j)
          for (int i = e.x0; i < e.x1(); ++i) f.at(i, j) += 37.5f + 3.0f * static_cast<float>((i * 7 + j * 3) % 5);
        heights = Buffer::from(std::span<const float>(f.heights));
        updated.update(heights, e);
        GpuPyramid fresh;
        fresh.build(heights, f.width, f.height, options, coefficients);
        ASSERT_EQ(updated.levels(), fresh.levels());
        for (int l = 0; l < fresh.levels(); ++l)
          ASSERT_EQ(updated.download_level(l), fresh.download_level(l)) << "level " << l << " after " << e.x0 << ","
                                                                        << e.y0 << " " << e.width << "×" << e.height;
        EXPECT_EQ(updated.max_coeff(), fresh.max_coeff());
      }
      EXPECT_NE(updated.download_level(std::min(1, updated.levels() - 1)), before) << "the edits reached level 1";
    }
}

TEST_F(GpuPyramidTest, AnUpdateNeedsAnUpdatableBuildAndARectangleInTheField) {
  const terrain::HeightField f = void_filled_field(40, 30, 8);
  const Buffer heights = Buffer::from(std::span<const float>(f.heights));
  GpuPyramid gpu;
  gpu.build(heights, f.width, f.height, terrain::PyramidOptions{.k_v = 4});
  EXPECT_THROW(gpu.update(heights, {1, 1, 2, 2}), std::logic_error);
  gpu.build(heights, f.width, f.height, terrain::PyramidOptions{.k_v = 4}, true, true);
  EXPECT_THROW(gpu.update(heights, {39, 0, 2, 2}), std::invalid_argument);
  EXPECT_THROW(gpu.update(heights, {-1, 0, 2, 2}), std::invalid_argument);
  EXPECT_NO_THROW(gpu.update(heights, {39, 29, 1, 1}));
}

TEST_F(GpuPyramidTest, RejectsBadInput) {
  GpuPyramid gpu;
  const Buffer small(16);
  EXPECT_THROW(gpu.build(small, 0, 4, {}), std::invalid_argument);
  EXPECT_THROW(gpu.build(small, 4, 4, {}), std::invalid_argument);  // 16 B < 4·4 floats
  EXPECT_THROW(gpu.build(small, 2, 2, terrain::PyramidOptions{.k_v = 0}), std::invalid_argument);
}

}  // namespace
}  // namespace skylit::gpu
