// The B-spline height pyramid built on the GPU (DESIGN.md pipeline step 2): the same
// levels as terrain::HeightPyramid — level l ≥ 1 the level-0 piecewise-linear heights
// filtered by β3 at the level's texel size, separably (shaders/pyramid_filter.comp),
// then every level's interpolating B-spline coefficients by the edge-clamped
// tridiagonal solve, rows then columns (shaders/pyramid_coeffs.comp) — to float32
// rounding (tests/gpu_pyramid_test.cpp).
//
// C++ supplies everything that is not arithmetic on heights, from terrain/pyramid.h's
// own functions: level sizes and steps (pyramid_level_shape), the filter taps
// (reduction_axis_taps) and the solve's LU factors (bspline_factors). They depend on
// the field's size alone, so they are uploaded once per size and kept.
//
// Output layout (what shaders/horizon_march.comp reads): every level's coefficients
// row-major, levels one after another in one buffer, each starting at a multiple of
// GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT (padding between them); shape(l) and
// offset(l) give each level's geometry (the march's step table carries it per step,
// gpu_pipeline.cpp). The kernels bind one level's range at a time, so the storage-block
// size limit bounds a level, not the whole pyramid; the march reads the whole buffer
// through one buffer texture, bounded by GL_MAX_TEXTURE_BUFFER_SIZE.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "gpu/buffers.h"
#include "gpu/compute_program.h"
#include "terrain/height_field.h"
#include "terrain/pyramid.h"

namespace skylit::gpu {

class GpuPyramid {
 public:
  // Compiles the two kernels. Needs a current GL 4.5 context for its whole life.
  // max_binding_bytes: the largest storage range a level or the filter scratch may be
  // bound as, 0 for the driver's GL_MAX_SHADER_STORAGE_BLOCK_SIZE (tests lower it to
  // exercise the limit on small fields, whose tap tables it does not bound).
  explicit GpuPyramid(std::size_t max_binding_bytes = 0);

  // Builds every level of the pyramid of the width × height field whose level-0
  // heights (row-major float32) are in `heights`: the levels' B-spline coefficients, or
  // with `coefficients` false their samples (for bilinear sampling, no solve). Geometry
  // tables and buffers are (re)made only when the size or options change. Returns the bytes uploaded (the
  // tables, or 0 when they were kept). Throws std::invalid_argument for a bad size or
  // options, std::runtime_error when one level exceeds the storage-block limit or all
  // levels the buffer-texture limit.
  // With `updatable`, it also keeps what update() reads: every level's x-filtered rows
  // and samples (Σ level widths × height + Σ level sizes floats: 8.7× the field at k_v 4).
  std::size_t build(const Buffer& heights, int width, int height, const terrain::PyramidOptions& options,
                    bool coefficients = true, bool updatable = false);
  // After the field's heights changed inside `dirty` only (since the last build or
  // update, which was updatable): filters again only the outputs whose taps read an
  // edited texel, then solves every level as build() does, so the result is build()'s bit
  // for bit (tests/gpu_pyramid_test.cpp). The filters are most of a build's time and an
  // edit reaches few of their outputs at the fine levels. Throws std::logic_error without
  // an updatable build, std::invalid_argument for a rectangle outside the field.
  void update(const Buffer& heights, const terrain::PixelRect& dirty);
  bool updatable() const { return mUpdatable; }

  int levels() const { return static_cast<int>(mShapes.size()); }
  const terrain::LevelShape& shape(int l) const { return mShapes.at(l); }
  std::size_t offset(int l) const { return mOffsets.at(l); }  // first coefficient of level l (floats)
  const Buffer& coeffs() const { return mCoeffs; }
  // The largest value (coefficient or sample) of all levels (4 bytes read back; NaN if any is NaN).
  float max_coeff() const;
  // Level l's coefficients (or samples), downloaded (tests).
  std::vector<float> download_level(int l) const;

 private:
  // Binds level l's coefficients as the storage block at `binding`.
  void bind_level(unsigned binding, int l) const;
  // Level 0 and the filters of levels ≥ 1 over the outputs that read `window` (all of
  // them for the whole field), then every level's solve.
  void compute(const Buffer& heights, const terrain::PixelRect& window);

  ComputeProgram mFilter, mSolve;
  std::size_t mMaxBindingBytes;
  int mWidth = 0, mHeight = 0;
  terrain::PyramidOptions mOptions;
  std::vector<terrain::LevelShape> mShapes;
  std::vector<std::size_t> mOffsets;
  // Per level: tap-table base of the x and y passes (l ≥ 1), pivot-table base of the
  // row and column solves, in mTaps / mWeights; the inputs each output reads, clamped
  // (first, last) per axis, for update()'s windows.
  struct LevelTables {
    int taps_x = 0, taps_y = 0, factors_x = 0, factors_y = 0;
    std::vector<std::pair<int, int>> reads_x, reads_y;
  };
  std::vector<LevelTables> mTables;
  bool mCoefficients = true, mUpdatable = false;
  Buffer mTaps, mWeights, mCoeffs, mScratch, mMaxKey;
  // Updatable builds: each level's x-filtered rows (height × its width) and the levels'
  // samples (mCoeffs' layout).
  std::vector<Buffer> mRows;
  Buffer mSamples;
};

}  // namespace skylit::gpu
