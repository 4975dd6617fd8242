#include "gpu/gpu_pyramid.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include "gpu/gl_context.h"
#include "gpu/buffers.h"

namespace skylit::gpu {
namespace {

// Binding points of the pyramid kernels (their own dispatches; rebound every build).
enum Binding : int { kSrc = 0, kDst = 1, kTaps = 2, kWeights = 3, kCoeffs = 4, kMax = 5 };
constexpr int kLocal2d = 8;   // 8×8 outputs per filter work group
constexpr int kLocal1d = 64;  // lines per solve work group

GlslDefines filter_defines() {
  GlslDefines d;
  d.set("LOCAL_SIZE_X", kLocal2d)
      .set("LOCAL_SIZE_Y", kLocal2d)
      .set("SRC_BINDING", kSrc)
      .set("DST_BINDING", kDst)
      .set("TAPS_BINDING", kTaps)
      .set("WEIGHTS_BINDING", kWeights);
  return d;
}

GlslDefines solve_defines() {
  GlslDefines d;
  d.set("LOCAL_SIZE_X", kLocal1d)
      .set("COEFFS_BINDING", kCoeffs)
      .set("WEIGHTS_BINDING", kWeights)
      .set("MAX_BINDING", kMax)
      .set("OFF_DIAGONAL", terrain::kBSplineOffDiagonal);
  return d;
}

void check_heights(const Buffer& heights, int width, int height) {
  if (heights.size_bytes() < static_cast<std::size_t>(width) * height * sizeof(float))
    throw std::invalid_argument("GPU pyramid: the heights buffer is smaller than the field");
}

int to_index(std::size_t v, const char* what) {
  if (v > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw std::runtime_error(std::string("GPU pyramid: ") + what + " exceeds 32-bit indexing");
  return static_cast<int>(v);
}

// Appends the taps of one axis of one level, and each output's clamped inputs to
// `reads`; returns the base entry in `taps`.
int append_taps(int n_in, int n_out, std::vector<std::int32_t>& taps, std::vector<float>& weights,
                std::vector<std::pair<int, int>>& reads) {
  const int base = static_cast<int>(taps.size() / 4);
  for (const terrain::ReductionTaps& t : terrain::reduction_axis_taps(n_in, n_out)) {
    const int last = t.first + static_cast<int>(t.weight.size()) - 1;
    reads.emplace_back(std::clamp(t.first, 0, n_in - 1), std::clamp(last, 0, n_in - 1));
    const std::int32_t entry[4] = {t.first, static_cast<std::int32_t>(t.weight.size()),
                                   to_index(weights.size(), "the filter taps"), 0};
    taps.insert(taps.end(), entry, entry + 4);
    for (double w : t.weight) weights.push_back(static_cast<float>(w));
  }
  return base;
}

// Appends pivot[0..n) then upper[0..n); returns the pivots' first entry.
int append_factors(int n, std::vector<float>& weights) {
  const int base = to_index(weights.size(), "the filter taps");
  const terrain::BSplineFactors lu = terrain::bspline_factors(n);
  for (double p : lu.pivot) weights.push_back(static_cast<float>(p));
  for (double u : lu.upper) weights.push_back(static_cast<float>(u));
  return base;
}

// The outputs [first, end) whose reads meet inputs [lo, hi): contiguous, since the
// taps' windows move monotonically along the axis.
std::pair<int, int> outputs_reading(const std::vector<std::pair<int, int>>& reads, int lo, int hi) {
  int first = static_cast<int>(reads.size()), end = 0;
  for (int o = 0; o < static_cast<int>(reads.size()); ++o)
    if (reads[o].first < hi && reads[o].second >= lo) first = std::min(first, o), end = o + 1;
  return {first, std::max(first, end)};
}

}  // namespace

GpuPyramid::GpuPyramid(std::size_t max_binding_bytes)
    : mFilter(ComputeProgram::from_embedded("pyramid_filter.comp", filter_defines())),
      mSolve(ComputeProgram::from_embedded("pyramid_coeffs.comp", solve_defines())),
      mMaxBindingBytes(max_binding_bytes) {}

void GpuPyramid::bind_level(unsigned binding, int l) const {
  const terrain::LevelShape& s = mShapes.at(l);
  mCoeffs.bind_storage_range(binding, mOffsets.at(l) * sizeof(float),
                             static_cast<std::size_t>(s.width) * s.height * sizeof(float));
}

std::size_t GpuPyramid::build(const Buffer& heights, int width, int height, const terrain::PyramidOptions& options,
                              bool coefficients, bool updatable) {
  if (width < 1 || height < 1) throw std::invalid_argument("GPU pyramid: empty height field");
  check_heights(heights, width, height);
  std::size_t uploaded = 0;
  const bool same = width == mWidth && height == mHeight && options.k_v == mOptions.k_v &&
                    options.levels == mOptions.levels && options.min_size == mOptions.min_size;
  if (!same) {  // geometry and tables for this size
    mWidth = mHeight = 0;  // none kept if a check below throws
    mRows.clear();
    mSamples = Buffer();
    const int n = terrain::pyramid_level_count(width, height, options);
    mShapes.clear();
    mOffsets.clear();
    mTables.assign(n, {});
    std::vector<std::int32_t> taps;
    std::vector<float> weights;
    // Level starts are bound as range offsets: multiples of the alignment, in floats.
    const std::size_t align = std::lcm(storage_offset_alignment(), sizeof(float)) / sizeof(float);
    std::size_t total = 0, scratch = 1;
    for (int l = 0; l < n; ++l) {
      const terrain::LevelShape s = terrain::pyramid_level_shape(width, height, options.k_v, l);
      const std::size_t size = static_cast<std::size_t>(s.width) * s.height;
      const std::string what = "GPU pipeline: level " + std::to_string(l) + " of the height pyramid";
      check_storage_size(size * sizeof(float), what.c_str(), mMaxBindingBytes);
      total = (total + align - 1) / align * align;
      mShapes.push_back(s);
      mOffsets.push_back(total);
      LevelTables& t = mTables[l];
      if (l > 0) {
        t.taps_x = append_taps(width, s.width, taps, weights, t.reads_x);
        t.taps_y = append_taps(height, s.height, taps, weights, t.reads_y);
        scratch = std::max(scratch, static_cast<std::size_t>(height) * s.width);
      }
      t.factors_x = append_factors(s.width, weights);
      t.factors_y = append_factors(s.height, weights);
      total += size;
    }
    if (taps.empty()) taps.assign(4, 0);  // GL wants non-empty buffers bound
    to_index(total, "the pyramid");  // the march indexes coefficients with int
    // The march reads all levels through one r32f buffer texture (gpu_pipeline.cpp).
    check_texture_buffer_size(total, "GPU pipeline: the height pyramid");
    check_storage_size(scratch * sizeof(float), "GPU pipeline: the pyramid's filter scratch", mMaxBindingBytes);
    check_storage_size(weights.size() * sizeof(float), "GPU pipeline: the pyramid's filter taps");
    mTaps = Buffer::from(std::span<const std::int32_t>(taps));
    mWeights = Buffer::from(std::span<const float>(weights));
    mCoeffs = Buffer(total * sizeof(float));
    mScratch = Buffer(scratch * sizeof(float));
    uploaded = mTaps.size_bytes() + mWeights.size_bytes();
    mWidth = width, mHeight = height, mOptions = options;
  }
  if (updatable && mSamples.size_bytes() == 0) {  // each level's x-filtered rows (each ≤ the scratch)
    mRows.clear();
    mRows.emplace_back(sizeof(float));  // level 0 has none
    for (int l = 1; l < levels(); ++l) mRows.emplace_back(static_cast<std::size_t>(height) * mShapes[l].width * sizeof(float));
    mSamples = Buffer(mCoeffs.size_bytes());
  }
  mCoefficients = coefficients;
  mUpdatable = updatable;
  compute(heights, {0, 0, width, height});
  return uploaded;
}

void GpuPyramid::update(const Buffer& heights, const terrain::PixelRect& dirty) {
  if (!mUpdatable) throw std::logic_error("GpuPyramid::update: the last build was not updatable");
  if (dirty.x0 < 0 || dirty.y0 < 0 || dirty.x1() > mWidth || dirty.y1() > mHeight)
    throw std::invalid_argument("GpuPyramid::update: the edited rectangle is outside the field");
  check_heights(heights, mWidth, mHeight);
  if (!dirty.empty()) compute(heights, dirty);
}

void GpuPyramid::compute(const Buffer& heights, const terrain::PixelRect& window) {
  const int width = mWidth, height = mHeight;
  mTaps.bind_storage(kTaps);
  mWeights.bind_storage(kWeights);
  const std::uint32_t no_key = 0;  // below every float's key
  mMaxKey = Buffer::from(std::span<const std::uint32_t>(&no_key, 1));
  mMaxKey.bind_storage(kMax);
  // Level 0 is the heights themselves.
  glCopyNamedBufferSubData(heights.id(), mCoeffs.id(), 0, static_cast<GLintptr>(mOffsets[0] * sizeof(float)),
                           static_cast<GLsizeiptr>(static_cast<std::size_t>(width) * height * sizeof(float)));
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
  // The filter reads through buffer textures (pyramid_filter.comp says why).
  const BufferTexture heights_tex(heights), weights_tex(mWeights);
  weights_tex.bind_sampler(kWeights);
  auto set_window = [&](int x0, int y0, int x1, int y1) {
    mFilter.set_uniform("out_x0", x0);
    mFilter.set_uniform("out_y0", y0);
    mFilter.set_uniform("out_x1", x1);
    mFilter.set_uniform("out_y1", y1);
  };
  for (int l = 0; l < levels(); ++l) {
    const terrain::LevelShape& s = mShapes[l];
    const LevelTables& t = mTables[l];
    if (l > 0) {
      // The outputs that read the window: columns along x, then rows along y.
      const auto [cx0, cx1] = outputs_reading(t.reads_x, window.x0, window.x1());
      const auto [ry0, ry1] = outputs_reading(t.reads_y, window.y0, window.y1());
      // x pass: level-0 rows → s.width values, into the scratch (or the level's kept rows).
      heights_tex.bind_sampler(kSrc);
      const Buffer& rows = mUpdatable ? mRows[l] : mScratch;
      rows.bind_storage(kDst);
      mFilter.set_uniform("axis", 0);
      mFilter.set_uniform("out_width", s.width);
      mFilter.set_uniform("n_in", width);
      mFilter.set_uniform("along_stride", 1);
      mFilter.set_uniform("across_stride", width);
      mFilter.set_uniform("tap_base", t.taps_x);
      set_window(cx0, window.y0, cx1, window.y1());
      mFilter.dispatch_covering(cx1 - cx0, window.height);
      // y pass: those rows' columns → the level's samples (kept, or in its coefficients' range).
      const BufferTexture rows_tex(rows);
      rows_tex.bind_sampler(kSrc);
      if (mUpdatable) {
        mSamples.bind_storage_range(kDst, mOffsets[l] * sizeof(float),
                                    static_cast<std::size_t>(s.width) * s.height * sizeof(float));
      } else {
        bind_level(kDst, l);
      }
      mFilter.set_uniform("axis", 1);
      mFilter.set_uniform("n_in", height);
      mFilter.set_uniform("along_stride", s.width);
      mFilter.set_uniform("across_stride", 1);
      mFilter.set_uniform("tap_base", t.taps_y);
      set_window(cx0, ry0, cx1, ry1);
      mFilter.dispatch_covering(cx1 - cx0, ry1 - ry0);
      if (mUpdatable)  // the solve below works in place: on a copy of the samples
        glCopyNamedBufferSubData(mSamples.id(), mCoeffs.id(), static_cast<GLintptr>(mOffsets[l] * sizeof(float)),
                                 static_cast<GLintptr>(mOffsets[l] * sizeof(float)),
                                 static_cast<GLsizeiptr>(static_cast<std::size_t>(s.width) * s.height * sizeof(float)));
    }
    // Coefficients: rows, then columns (without `coefficients`: the column pass's max only).
    bind_level(kCoeffs, l);
    mSolve.set_uniform("solve", mCoefficients ? 1 : 0);
    mSolve.set_uniform("lines", s.height);
    mSolve.set_uniform("n", s.width);
    mSolve.set_uniform("line_stride", s.width);
    mSolve.set_uniform("elem_stride", 1);
    mSolve.set_uniform("factor_base", t.factors_x);
    mSolve.set_uniform("track_max", 0);
    if (mCoefficients) mSolve.dispatch_covering(s.height);
    mSolve.set_uniform("lines", s.width);
    mSolve.set_uniform("n", s.height);
    mSolve.set_uniform("line_stride", 1);
    mSolve.set_uniform("elem_stride", s.width);
    mSolve.set_uniform("factor_base", t.factors_y);
    mSolve.set_uniform("track_max", 1);
    mSolve.dispatch_covering(s.width);
  }
  throw_on_gl_error("GpuPyramid::build");
}

float GpuPyramid::max_coeff() const {
  std::uint32_t key = 0;
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
  mMaxKey.download(&key, sizeof key, 0);
  return std::bit_cast<float>((key & 0x80000000u) != 0 ? key & 0x7fffffffu : ~key);
}

std::vector<float> GpuPyramid::download_level(int l) const {
  const terrain::LevelShape& s = shape(l);
  std::vector<float> out(static_cast<std::size_t>(s.width) * s.height);
  mCoeffs.download(out.data(), out.size() * sizeof(float), mOffsets.at(l) * sizeof(float));
  return out;
}

}  // namespace skylit::gpu
