// Multi-resolution horizon marching (SN08/NS09 §5.2, DESIGN.md pipeline step 3), CPU
// reference in double precision.
//
// From texel p with own height h₀ along heading u, step s = 0 … n_v−1 sits at
//   t_s = τ_s·D,   τ_s = 2^(−(n_v−1−s)/k_v)                  (NS09 eq. 14)
// so the last step is at the maximum distance D. Step s reads pyramid level
//   ℓ_s = round(k_v·log2(t_s·2^(−o_v) / texel)),  clamped to the pyramid,
// i.e. the level whose texel is 2^(−o_v) of the distance (o_v = 2: a quarter; the
// samples, 0.16·t apart at k_v = 4, then never skip a texel of their level).
// Blocking angle: ω_s = atan((f_ℓ(p + t_s u) − d²/(2R_eff) − h₀)/t_s), h₀ the
// pixel centre's own (unfiltered) height (DESIGN.md "Conventions").
// Samples leaving the grid end the ray. The result is the max over ω_s, or the max of
// their uniform cubic B-spline sampled at knots and midpoints (NS09 eq. 17, weights
// (1,4,1)/6 and (1,23,23,1)/48; end values replicated — the listing pads with 0,
// which drags the first knot toward the horizontal).
// Floors are applied by the callers: the tangent plane for visibility (✱ math-notes
// §10.14), the receiver's ground level for the `horizon` product.
#pragma once

#include "shading/horizon/azimuth.h"
#include "shading/horizon/earth_curvature.h"
#include "shading/horizon/horizon_ray.h"
#include "terrain/height_field.h"
#include "terrain/pyramid.h"

#include <glm/vec3.hpp>

#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace skylit::horizon {

enum class HorizonMethod { March, Sweep };
std::vector<HorizonMethod> all_horizon_methods();  // march first
// "march" or "sweep", as `skylit shade --horizons` and the bench name them.
std::string_view horizon_method_name(HorizonMethod method);
std::optional<HorizonMethod> parse_horizon_method(std::string_view name);

struct MarchOptions {
  int azimuths = 32;            // W
  int k_v = 4;                  // pyramid levels (and steps) per halving of resolution
  int levels = 0;               // n_v march steps; 0 = enough that t_0 ≤ one texel
  double level_offset = 3.0;    // o_v (NS09: 2; 3 measured 1/3 more accurate, docs/accuracy.md)
  double max_distance_m = 0.0;  // D; 0 = the DEM extent (diagonal)
  // The defaults below are the measured front's (docs/quality-presets.md), not NS09's
  // B-spline levels and smooth max: at 512² those cost 2× the time for more error.
  bool smooth_max = false;      // true: B-spline max of the blocking angles (NS09 eq. 17)
  bool use_pyramid = true;      // false: every step samples level 0 bilinearly
  // How a step reads its pyramid level: bilinear between the level's samples (4 reads)
  // or the cubic B-spline through them (NS09; 16 coefficients).
  terrain::Interpolation level_interpolation = terrain::Interpolation::Bilinear;
  EarthCurvature curvature;     // on by default
  // How horizons are found: rays per texel over the pyramid ("march", the knobs above)
  // or sweep lines holding convex hulls ("sweep", horizon_sweep.h, the knobs below),
  // which marches instead where it does not apply (sweep_applicable). The sweep by
  // default: on projected real DEMs it has 1/5 of the march's svf RMSE and 1/7 of its
  // skyview RMSE at 1/3 of its CPU time (docs/accuracy.md), and half its GPU time.
  HorizonMethod method = HorizonMethod::Sweep;
  int sweep_near_steps = 4;  // K: half-texel steps each texel takes along its own ray
  int sweep_lines = 1;       // sweep lines per texel across the heading (1/Δc)
  // The texels whose horizons are wanted (empty: all). The sweep skips the lines that
  // own none of them and the samples that reach none of them; the others' far slopes are
  // then left unset (kFarCodeNone). A window's halo is only blockers (tiles, blocks).
  terrain::PixelRect region{};
};

// How a step reads heights, as `skylit shade --levels` and the bench name it:
// the pyramid level by cubic B-spline ("bspline", NS09) or bilinearly ("bilinear"), or
// level 0 bilinearly with no pyramid ("none").
enum class LevelSampling { BSpline, Bilinear, None };
LevelSampling level_sampling(const MarchOptions& options);
void set_level_sampling(MarchOptions& options, LevelSampling sampling);
std::vector<LevelSampling> all_level_samplings();  // NS09's first
std::string_view level_sampling_name(LevelSampling sampling);
std::optional<LevelSampling> parse_level_sampling(std::string_view name);
// "smooth" (B-spline max, NS09 eq. 17) or "plain", as `--horizon-max` names them.
std::string_view horizon_max_name(bool smooth_max);

// Throws std::invalid_argument for W < 1, k_v < 1, n_v < 0, D < 0, non-finite values,
// sweep near steps < 0 or sweep lines < 1.
void validate(const MarchOptions& options);

// Maximum marching distance D (m) that `options` resolves to on `field`.
double resolved_max_distance(const terrain::HeightField& field, const MarchOptions& options);

// n_v that puts the first step within one (smallest-side) texel: ⌈k_v·log2(D/texel)⌉ + 1.
int auto_march_levels(double max_distance, double texel, int k_v);

// Tangent-plane elevation of heading u for unit normal n (east, north, up):
// −atan(N_h·u / N_z). Directions at or below it face into the surface.
double tangent_plane_floor(const glm::dvec3& normal, Heading u);

// The step schedule: t_s (m) and pyramid level ℓ_s of each step s (formulas above),
// clamped to the levels HeightPyramid would build for `field` (0 without use_pyramid).
// Needs no pyramid: the GPU path builds its own (gpu/gpu_pyramid.h).
struct MarchSchedule {
  std::vector<double> distances;
  std::vector<int> levels;
};
MarchSchedule march_schedule(const terrain::HeightField& field, const MarchOptions& options);

// Exact early exit of the march: every height a step reads is a convex combination of
// pyramid coefficients (level-0 heights when bilinear), so ≤ their max z; a step at
// t' ≥ t then has angle ≤ atan(max(z − h0, 0)/t). Slack on z (float sums overshoot
// by ulps) and on the angle comparison keeps the exit from ever changing a result.
struct MarchExitSlack {
  static constexpr double height_rel = 1e-4, height_abs = 1e-2;  // z_bound = z + rel·|z| + abs (m)
  static constexpr double angle = 1e-6;                          // rad
  static constexpr int smooth_window = 4;                        // angles per smooth-max window
};
// max_height plus the slack; +∞ (no exit) unless max_height is finite.
double march_exit_height_bound(double max_height);
// The same for the largest of `values` (NaN, i.e. nodata, skipped; +∞ if none).
double march_exit_height_bound(std::span<const float> values);

// The pyramid options the march samples (k_v levels per halving, automatic count).
terrain::PyramidOptions march_pyramid_options(const MarchOptions& options);

class HorizonMarcher {
 public:
  // Builds the B-spline pyramid (k_v levels per halving) unless use_pyramid is off.
  HorizonMarcher(const terrain::HeightField& field, const MarchOptions& options);

  // Largest blocking angle (radians) from texel (i, j) along u; −∞ if no step lies
  // on the grid. Thread-safe. early_exit false: every step (tests of the exit).
  // steps_marched, if given, receives the steps read.
  double max_elevation(int i, int j, Heading u, bool early_exit = true, int* steps_marched = nullptr) const;
  // Offset marching (seed 000 §4.1, "height field cast shadows"): the same march from a
  // point off the texel centres, at height h0 (m) instead of the ground's, e.g. an
  // aircraft's sphere centre; `origin` in level-0 texels, on the grid.
  double max_elevation_from(GridPoint origin, double h0, Heading u, bool early_exit = true,
                            int* steps_marched = nullptr) const;

  int steps() const { return static_cast<int>(schedule_.distances.size()); }
  double distance(int s) const { return schedule_.distances[s]; }  // t_s (m)
  int level_of_step(int s) const { return schedule_.levels[s]; }
  double max_distance() const { return schedule_.distances.back(); }
  const MarchSchedule& schedule() const { return schedule_; }
  const MarchOptions& options() const { return options_; }
  // The B-spline pyramid the march samples (empty when use_pyramid is off).
  const terrain::HeightPyramid& pyramid() const { return pyramid_; }

 private:
  double height_at(int step, GridPoint p) const;

  const terrain::HeightField& field_;
  MarchOptions options_;
  terrain::HeightPyramid pyramid_;
  MarchSchedule schedule_;
  double z_bound_ = 0.0;  // march_exit_height_bound of every height the march reads
};

}  // namespace skylit::horizon
