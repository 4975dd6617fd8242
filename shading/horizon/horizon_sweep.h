// Horizon sweep: the exact march's horizons (horizon_exact.h) at a cost linear in the
// DEM's size per azimuth, instead of the multi-resolution march's per-texel rays.
//
// Along heading u the exact march from texel p samples p + n·δ, n = 1, 2, …, with δ
// half a texel of the dominant axis (exact_step_length). On a grid whose rows share one
// spacing δ is the same in texel units for every texel, so the rays are parallel lines
// b = c + r·a (a the dominant axis, b the other, r = δ_b/δ_a, |r| ≤ 1). One sweep line
// per Δc = 1/lines_per_texel of c runs over the grid against u, keeping the upper convex
// hull of its samples (s, Z) already passed (Andrew's monotone chain: each sample is
// pushed and popped at most once). Earth curvature stays exact on the hull:
//   (z − t²/(2R) − h₀)/t = (Z − H₀)/t + s₀/R,  Z = z − s²/(2R), H₀ = h₀ − s₀²/(2R),
// with s the distance along the line and t = s − s₀ (math-notes; checked by the tests).
// The max over the hull of (Z − H₀)/t is its tangent from (s₀, H₀), found by walking
// down the chain from its nearest vertex while the slope rises (unimodal on a convex
// chain).
//
// A texel takes its far field (samples n ≥ near_steps + 1) from the line nearest to it
// (|c − c_texel| ≤ Δc/2: a lateral offset of at most Δc/2 texels), queried with its own
// height h₀ — the line inserts each sample near_steps + 1 half-steps after passing it,
// so the hull holds exactly the far samples. The first near_steps samples come from the
// texel's own ray, as the exact march takes them; a ray that leaves the grid among them
// ends there (no far field), as in the exact march.
//
// On a geographic grid (rows of different spacing) the rays are rhumb lines, which in
// the stretched row coordinate Γ of rhumb_rows.h are straight lines of one slope r per
// heading: b = c + r·Γ(a) when the rows are the dominant axis, Γ(b) = c + r·a when the
// columns are, so the same lines, hulls and owners apply with Γ in place of the row.
// Samples stay on the dominant axis's half texels; along columns their spacing in metres
// follows D(y) (the hull holds positions p in reference steps, p = n on rows and on
// projected grids). The owner line is within Δc/2 of the texel in Γ, i.e. within
// Δc/2·D/D_ref rows.
//
// A maximum distance D below the DEM's diagonal bounds the far field as the exact march
// does (t ≤ D): the samples within D of an observer are a window that gains the nearest
// sample and loses the farthest, held as two hulls, a queue of two stacks (the newest
// samples' hull, and the older ones' built outwards from the nearest with what each push
// hid, so that the farthest can be popped); a sample is pushed at most twice, and the
// older hull is bisected for its tangent.
//
// Needs rows whose spacings differ by less than kMaxRowSpacingRatio (nearer a pole the
// march is used) and a distance beyond the near steps: sweep_applicable says when;
// elsewhere callers march. Cost per azimuth: about 2·sweep_lines·(1 + |r|)·N² samples,
// each pushed once (twice when bounded), and one hull walk per texel.
#pragma once

#include "shading/horizon/azimuth.h"
#include "shading/horizon/horizon_march.h"
#include "terrain/height_field.h"

#include "shading/horizon/rhumb_rows.h"

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace skylit::horizon {

// Largest ratio of the rows' spacings the sweep takes: 2 spans 60° N … 75° N, or any
// 1° tile south of 88.5° N; nearer a pole the metric grid of horizon_ray.h breaks down.
inline constexpr double kMaxRowSpacingRatio = 2.0;
// |r| below which a curved line led by columns counts as due east (its positions along
// the line then come from its row's spacing; horizon_sweep.cpp).
inline constexpr double kDueEastSlope = 1e-6;

// True when the rows' spacings stay within kMaxRowSpacingRatio and the maximum distance
// (if bounded) reaches past the near steps (MarchOptions::sweep_near_steps, sweep_lines:
// see there).
bool sweep_applicable(const terrain::HeightField& field, const MarchOptions& options);
// Why it is false, for messages ("" when it applies): the rows' spacings differ too much,
// or the maximum distance ends within the near steps of half texels.
std::string sweep_inapplicable_reason(const terrain::HeightField& field, const MarchOptions& options);
// True when the maximum distance is below the diagonal between the corner texels: the far
// field is a window (header; horizon_sweep.comp keeps the same window).
bool sweep_bounded(const terrain::HeightField& field, const MarchOptions& options);

// Geometry of the sweep lines of one heading (texel units), shared with the GPU.
struct SweepGeometry {
  bool x_dominant = true;  // a = column (x) if true, else row (y)
  double step_m = 0.0;     // metric length of one half-texel step (exact_step_length)
  double delta_a = 0.5;    // ±0.5: the dominant-axis texels per step, toward the blockers
  double r = 0.0;          // b per unit a along the ray (in Γ for the row axis: curved)
  int extent_a = 0, extent_b = 0;  // texels along a and b
  int samples = 0;         // M = 2(extent_a − 1) + 1 samples per line, a on half texels
  double c_low = 0.0;      // c of line 0
  int lines_per_texel = 2;
  double spacing() const { return 1.0 / lines_per_texel; }  // Δc between lines
  int lines = 0;
  // Rows of different spacing (rhumb_rows.h); null on one spacing (Γ = y).
  std::shared_ptr<const RhumbRows> rows;
  bool curved() const { return rows != nullptr; }
  // Dominant-axis coordinate of sample n of a line (n = 0 at the grid's upwind edge).
  double a_at(int n) const { return (delta_a > 0.0 ? 0.0 : extent_a - 1.0) + n * delta_a; }
  // The line a texel (whole a, b) takes its far field from: the nearest, ties to the
  // higher c: ⌊(b − r·a − c_low)·lines_per_texel + ½⌋ in double, one multiply and adds
  // (correctly rounded on every GPU), so the GLSL twin picks the same line. Curved: the
  // row coordinate is Γ, from RhumbRows::half_rows (the GPU reads the same doubles).
  int owner(double a, double b) const;
  // c of the line through texel coordinates (a, b), before rounding to a line.
  double line_c(double a, double b) const;
};

// `rows`: the field's RhumbRows when its rows' spacings differ (made here when null).
SweepGeometry sweep_geometry(const terrain::HeightField& field, Heading u, int lines_per_texel,
                             std::shared_ptr<const RhumbRows> rows = nullptr);

// The far slopes are stored in 16 bits per texel and heading, on the CPU as on the GPU:
// half a float array's memory, which is W layers of the whole field (and dear to touch
// on the CI VM). Code q holds x = s/(1 + |s|) ∈ (−1, 1) rounded down to a multiple of
// 1/h, h = kFarCodeHalfRange: q = h + ⌊x·h⌋, clamped to [1, kFarCodeMax]; 0 is "none"
// (s = −∞, x = −1). Decoding: x = q/h − 1, s = x/(1 − |x|). Rounding down never raises
// a horizon (open ground stays open; slope 0 is code h exactly), and as
// dθ/dx = (1 + |s|)²/(1 + s²) ∈ [1, 2] it lowers one by less than 2/h ≈ 6e-5 rad at
// every slope (≈ 0.0035°, against the sweep's ~0.4° RMSE). ⌊x·h⌋ rather than
// ⌊(x + 1)·h⌋: float keeps x·h exact enough near 0, where x + 1 would round. The GLSL
// twins are in shaders/horizon_sweep.comp and shaders/horizon_near.glsl.
inline constexpr int kFarCodeHalfRange = 32767;
inline constexpr int kFarCodeNone = 0;
inline constexpr int kFarCodeMax = 2 * kFarCodeHalfRange - 1;  // one more would be x = 1, s = +∞
std::uint16_t encode_far_slope(double slope);
float decode_far_slope(std::uint16_t code);

// The far field's window along g's lines, in steps of g.step_m: the samples within the
// maximum distance of an observer, as far as the exact march takes them (t ≤ D, with its
// 1e-12 of slack); +∞ unless sweep_bounded. Shared with horizon_sweep.comp's limit_steps.
double sweep_window_steps(const terrain::HeightField& field, const SweepGeometry& g, const MarchOptions& options);

// Far-field slope codes of every texel for heading u, [j·width + i]: the max over the
// texel's owner line's samples n ≥ sweep_near_steps + 1 of (z − t²/(2R) − h₀)/t
// (t = (n − n₀)·step_m ≤ the maximum distance, if bounded), encode_far_slope'd (kFarCodeNone if none), with the lines
// spread over `threads` (0: every core; the result does not depend on it). Throws
// std::invalid_argument unless applicable.
// `floor_slope` > 0 (tan; the sun's: only slopes near its disc matter): a texel whose far
// slope is below it gets a lower code or kFarCodeNone (a max over fewer samples); every
// other texel gets its code as without the floor. On straight lines (one row spacing)
// the sweep first bounds each observer's samples by the 3 × 3 maxima of the heights
// beside them (an O(1) running maximum per sample), then runs the hull for the observers
// it could not settle and the samples within reach of their floor lines alone; elsewhere
// the floor changes nothing.
// `observer_step` s > 1 (a sub-sampled field's, horizon_subsample.h): only the coarse
// texels get codes, the same as with s = 1; the others are left kFarCodeNone.
std::vector<std::uint16_t> sweep_far_slopes(const terrain::HeightField& field, Heading u, const MarchOptions& options,
                                            unsigned threads = 1,
                                            double floor_slope = -std::numeric_limits<double>::infinity(),
                                            int observer_step = 1);

// Raw horizon (rad) of texel (i, j): the near steps of its own ray and its far slope
// (code from sweep_far_slopes); −∞ if the first step already leaves the grid. Equals
// exact_max_elevation up to the far field's lateral offset and its code's rounding.
double sweep_max_elevation(const terrain::HeightField& field, int i, int j, Heading u, std::uint16_t far_code,
                           const MarchOptions& options);

}  // namespace skylit::horizon
