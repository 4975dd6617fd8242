// CPU reference height pyramid (NS09 §5.2): level l is the height field low-passed by a
// cubic B-spline and resampled so that its resolution is 2^(l/k_v) times coarser.
//
// COORDINATE CONVENTION (the horizon marcher relies on it)
//  * Every level covers exactly the extent of level 0 (the DEM's pixel footprints).
//  * Level coordinates (x, y) are in that level's texels: integer (i, j) is the CENTRE
//    of texel (i, j); x grows east (columns), y grows south (rows), like HeightField.
//    The level's extent is [−0.5, W_l − 0.5] × [−0.5, H_l − 0.5].
//  * Level l has W_l = max(1, round(W_0 / 2^(l/k_v))) columns (H_l likewise), so its
//    texel measures step_x = W_0 / W_l by step_y = H_0 / H_l level-0 texels (exact,
//    ≈ 2^(l/k_v); the extent is preserved, not the nominal ratio).
//  * Level-0 texel coordinates map to level l by the texel-centre rule
//      x_l = (x_0 + 0.5) / step_x − 0.5,      y_l = (y_0 + 0.5) / step_y − 0.5
//    (the same as GPU textures sampled at u = (x_0 + 0.5) / W_0).
//    HeightPyramid::sample() takes level-0 coordinates and does this for you.
//  * Metric: one level texel spans dx(j) metres east and dy metres north; level-0 pixel
//    centre (i, j) sits at metric (i·dx, −j·dy) (see height_field.h). For a metric
//    offset (east e, north n) from level-0 position (x_0, y_0):
//      x_0' = x_0 + e / field.dx(row), y_0' = y_0 − n / field.dy.
//  * Clamp-to-edge: positions are clamped to the span of texel centres [0, W_l − 1] ×
//    [0, H_l − 1] before interpolating, so outside the grid the edge value continues
//    (GL_CLAMP_TO_EDGE). A NaN coordinate is treated as 0.
//
// FILTERS
//  * Level 0 is the height field itself (filled heights; no smoothing).
//  * Level l ≥ 1: value at a level-texel centre p (in level-0 texels) is
//      ∫ L_0(x) β3((p − x)/s) / s dx  (separably in x with s = step_x, in y with step_y)
//    where L_0 is the piecewise-linear interpolant of level 0 (edge-clamped) and β3
//    the centred cubic B-spline (support 4s). The weights sum to 1 and reproduce
//    linear functions exactly away from the edges (> 2s + 1 texels), for any s.
//  * sample_bspline: cubic B-spline interpolation. Each level also stores coefficients
//    c with Σ_k c[clamp(k)] β3(x − k) = samples at every texel centre (exact tridiagonal
//    solve with edge-clamped coefficients), so the spline passes through the samples
//    and is C², and reproduces linear functions.
//  * sample_bilinear: bilinear interpolation of the samples.
#pragma once

#include <cstdint>
#include <vector>

#include "terrain/height_field.h"

namespace skylit::terrain {

struct PyramidOptions {
  int k_v = 4;       // levels per halving of resolution (≥ 1)
  int levels = 0;    // n_v; 0 = as many as keep the coarsest level's short side ≥ min_size
  int min_size = 2;  // texels, for the automatic level count
};

struct PyramidLevel {
  int width = 0, height = 0;
  double step_x = 1.0, step_y = 1.0;  // texel size in level-0 texels (W_0/W_l, H_0/H_l)
  double dy = 1.0;                    // metres per level texel, north–south
  std::vector<double> dx_per_row;     // metres per level texel, east–west, per level row
  std::vector<float> samples;         // filtered heights at texel centres, row-major (m)
  std::vector<float> coeffs;          // B-spline coefficients interpolating `samples`

  float sample_at(int i, int j) const { return samples[static_cast<std::size_t>(j) * width + i]; }
  double dx(int j) const { return dx_per_row[j]; }
  // Level-0 texel coordinate → this level's texel coordinate (texel-centre rule).
  double to_level_x(double x0) const { return (x0 + 0.5) / step_x - 0.5; }
  double to_level_y(double y0) const { return (y0 + 0.5) / step_y - 0.5; }
};

// Interpolation at level coordinates (x, y), clamp-to-edge (see above).
float sample_bilinear(const PyramidLevel& level, double x, double y);
float sample_bspline(const PyramidLevel& level, double x, double y);

enum class Interpolation { Bilinear, CubicBSpline };

class HeightPyramid {
 public:
  HeightPyramid() = default;
  explicit HeightPyramid(const HeightField& field, const PyramidOptions& options = {});

  void build(const HeightField& field, const PyramidOptions& options = {});
  // True when built from another size or revision of `field` (or never built).
  bool is_stale(const HeightField& field) const;
  // Brings the pyramid up to date: nothing if current; only the texels reached by the
  // last edit when exactly one edit (field.last_dirty) happened since; else a rebuild.
  // Returns true if anything was recomputed.
  bool update(const HeightField& field);

  int levels() const { return static_cast<int>(levels_.size()); }
  const PyramidLevel& level(int l) const { return levels_.at(l); }
  const PyramidOptions& options() const { return options_; }
  std::uint64_t source_revision() const { return revision_; }
  // Nominal resolution ratio of level l: 2^(l/k_v).
  double nominal_scale(int l) const;

  // Height of level l at level-0 texel coordinates (x0, y0).
  float sample(int l, double x0, double y0, Interpolation interp = Interpolation::CubicBSpline) const;

 private:
  void compute_level(const HeightField& field, int l, const PixelRect& region);
  PyramidOptions options_;
  std::vector<PyramidLevel> levels_;
  std::uint64_t revision_ = 0;
  int width_ = 0, height_ = 0;
  bool built_ = false;
};

// Automatic level count for a w × h field.
int auto_pyramid_levels(int width, int height, const PyramidOptions& options);

// ---- The construction's pieces, shared with the GPU build (gpu/gpu_pyramid.h) ----

// Level count HeightPyramid::build gives a w × h field (options.levels, or automatic).
int pyramid_level_count(int width, int height, const PyramidOptions& options);

struct LevelShape {
  int width = 0, height = 0;
  double step_x = 1.0, step_y = 1.0;  // W_0/W_l, H_0/H_l
};
// Size and texel size of level l of a w × h field (COORDINATE CONVENTION above).
LevelShape pyramid_level_shape(int width, int height, int k_v, int l);

// Weights of one output texel of a level's reduction along one axis (FILTERS above):
// input sample first + q, clamped to the grid, gets weight[q]; they sum to 1.
struct ReductionTaps {
  int first = 0;
  std::vector<double> weight;
};
// Taps of every output texel when n_in level-0 texels reduce to n_out.
std::vector<ReductionTaps> reduction_axis_taps(int n_in, int n_out);

// LU factors of the n × n edge-clamped B-spline interpolation system
// (c[i−1] + 4c[i] + c[i+1])/6 = f[i], c[−1] = c[0], c[n] = c[n−1] (Thomas algorithm):
//   forward  d[i] = (f[i] − kBSplineOffDiagonal·d[i−1]) / pivot[i]
//   backward c[i] = d[i] − upper[i]·c[i+1]   (c[n−1] = d[n−1])
inline constexpr double kBSplineOffDiagonal = 1.0 / 6.0;
struct BSplineFactors {
  std::vector<double> pivot, upper;
};
BSplineFactors bspline_factors(int n);

}  // namespace skylit::terrain
