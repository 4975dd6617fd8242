#include "shading/horizon/horizon_march.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace skylit::horizon {

void validate(const MarchOptions& o) {
  if (o.azimuths < 1) throw std::invalid_argument("march: azimuths must be ≥ 1");
  if (o.k_v < 1) throw std::invalid_argument("march: k_v must be ≥ 1");
  if (o.levels < 0) throw std::invalid_argument("march: levels must be ≥ 0 (0 = automatic)");
  if (!std::isfinite(o.level_offset)) throw std::invalid_argument("march: level offset must be finite");
  if (!(o.max_distance_m >= 0.0) || !std::isfinite(o.max_distance_m))
    throw std::invalid_argument("march: max distance must be ≥ 0 (0 = DEM extent)");
  if (o.curvature.enabled && !(o.curvature.radius_m > 0.0 && o.curvature.refraction_k < 1.0))
    throw std::invalid_argument("march: Earth radius must be > 0 and refraction k < 1");
  if (o.sweep_near_steps < 0) throw std::invalid_argument("sweep: near steps must be ≥ 0");
  if (o.sweep_lines < 1) throw std::invalid_argument("sweep: lines per texel must be ≥ 1");
  if (!o.region.empty() && (o.region.x0 < 0 || o.region.y0 < 0))
    throw std::invalid_argument("march: the wanted region must not start at a negative texel");
}

std::vector<HorizonMethod> all_horizon_methods() { return {HorizonMethod::March, HorizonMethod::Sweep}; }

std::string_view horizon_method_name(HorizonMethod method) {
  return method == HorizonMethod::Sweep ? "sweep" : "march";
}

std::optional<HorizonMethod> parse_horizon_method(std::string_view name) {
  for (HorizonMethod m : all_horizon_methods())
    if (name == horizon_method_name(m)) return m;
  return std::nullopt;
}

LevelSampling level_sampling(const MarchOptions& o) {
  if (!o.use_pyramid) return LevelSampling::None;
  return o.level_interpolation == terrain::Interpolation::Bilinear ? LevelSampling::Bilinear : LevelSampling::BSpline;
}

void set_level_sampling(MarchOptions& o, LevelSampling sampling) {
  o.use_pyramid = sampling != LevelSampling::None;
  o.level_interpolation =
      sampling == LevelSampling::Bilinear ? terrain::Interpolation::Bilinear : terrain::Interpolation::CubicBSpline;
}

std::vector<LevelSampling> all_level_samplings() {
  return {LevelSampling::BSpline, LevelSampling::Bilinear, LevelSampling::None};
}

std::string_view level_sampling_name(LevelSampling sampling) {
  switch (sampling) {
    case LevelSampling::BSpline: return "bspline";
    case LevelSampling::Bilinear: return "bilinear";
    case LevelSampling::None: return "none";
  }
  return "?";
}

std::optional<LevelSampling> parse_level_sampling(std::string_view name) {
  for (LevelSampling s : all_level_samplings())
    if (name == level_sampling_name(s)) return s;
  return std::nullopt;
}

std::string_view horizon_max_name(bool smooth_max) { return smooth_max ? "smooth" : "plain"; }

double resolved_max_distance(const terrain::HeightField& field, const MarchOptions& o) {
  return o.max_distance_m > 0.0 ? o.max_distance_m : dem_extent(field);
}

int auto_march_levels(double max_distance, double texel, int k_v) {
  if (max_distance <= texel) return 1;
  return static_cast<int>(std::ceil(k_v * std::log2(max_distance / texel) - 1e-9)) + 1;
}

double tangent_plane_floor(const glm::dvec3& n, Heading u) {
  return -std::atan((n.x * u.east + n.y * u.north) / n.z);
}

double march_exit_height_bound(double z) {
  if (!std::isfinite(z)) return std::numeric_limits<double>::infinity();
  return z + MarchExitSlack::height_rel * std::abs(z) + MarchExitSlack::height_abs;
}

double march_exit_height_bound(std::span<const float> values) {
  float z = -std::numeric_limits<float>::infinity();
  for (float v : values)
    if (v > z) z = v;  // NaN never compares greater
  return march_exit_height_bound(static_cast<double>(z));
}

terrain::PyramidOptions march_pyramid_options(const MarchOptions& options) {
  return terrain::PyramidOptions{.k_v = options.k_v};
}

MarchSchedule march_schedule(const terrain::HeightField& field, const MarchOptions& options) {
  validate(options);
  const double d_max = resolved_max_distance(field, options);
  const double texel = min_texel_size(field);
  const int n_v = options.levels > 0 ? options.levels : auto_march_levels(d_max, texel, options.k_v);
  const int top_level =
      options.use_pyramid ? terrain::pyramid_level_count(field.width, field.height, march_pyramid_options(options)) - 1
                          : 0;
  MarchSchedule out;
  out.distances.resize(n_v);
  out.levels.resize(n_v);
  for (int s = 0; s < n_v; ++s) {
    const double t = d_max * std::exp2(-static_cast<double>(n_v - 1 - s) / options.k_v);
    out.distances[s] = t;
    const double level = options.k_v * (std::log2(t / texel) - options.level_offset);
    out.levels[s] = std::clamp(static_cast<int>(std::lround(level)), 0, top_level);
  }
  return out;
}

HorizonMarcher::HorizonMarcher(const terrain::HeightField& field, const MarchOptions& options)
    : field_(field), options_(options), schedule_(march_schedule(field, options)) {
  if (options_.use_pyramid) pyramid_.build(field_, march_pyramid_options(options_));
  // The bound grows with the maximum, so the largest per-level bound is the bound of all.
  z_bound_ = options_.use_pyramid ? -std::numeric_limits<double>::infinity() : march_exit_height_bound(field_.heights);
  const bool bilinear = level_sampling(options_) == LevelSampling::Bilinear;  // reads samples, not coefficients
  for (int l = 0; options_.use_pyramid && l < pyramid_.levels(); ++l)
    z_bound_ = std::max(z_bound_, march_exit_height_bound(bilinear ? pyramid_.level(l).samples : pyramid_.level(l).coeffs));
}

double HorizonMarcher::height_at(int step, GridPoint p) const {
  if (!options_.use_pyramid) return bilinear_height(field_, p);
  return pyramid_.sample(schedule_.levels[step], p.x, p.y, options_.level_interpolation);
}

double HorizonMarcher::max_elevation(int i, int j, Heading u, bool early_exit, int* steps_marched) const {
  return max_elevation_from(GridPoint{static_cast<double>(i), static_cast<double>(j)}, field_.at(i, j), u, early_exit,
                            steps_marched);
}

double HorizonMarcher::max_elevation_from(GridPoint origin, double h0, Heading u, bool early_exit,
                                          int* steps_marched) const {
  // Slopes tan ω_s of the steps that lie on the grid (a prefix of the schedule).
  // atan is monotonic, so angles are taken only where the result needs them.
  constexpr int kInline = 64;
  double slope_buf[kInline], angle_buf[kInline];
  std::vector<double> slope_heap, angle_heap;
  double* q = slope_buf;
  double* w = angle_buf;
  if (steps() > kInline) {
    slope_heap.resize(steps()), angle_heap.resize(steps());
    q = slope_heap.data(), w = angle_heap.data();
  }
  int m = 0, steepest = 0;
  // Early exit (MarchExitSlack): stop once the bound at step s is below what the
  // steps so far already give; the smooth max still reads the 3 steps whose windows
  // hold earlier angles (the rest only add windows ≤ the bound, harmless).
  int stop = early_exit ? steps() : -1;
  // Max of the windows (knot s' and midpoint: angles s'−1 … s'+2, start clamped) within
  // the first m slopes, kept as m grows: ≤ the final result.
  int windows = 0, angles = 0;
  double running = -std::numeric_limits<double>::infinity();
  auto smooth_lower_bound = [&] {
    for (; angles < m; ++angles) w[angles] = std::atan(q[angles]);
    for (; windows + 2 < m; ++windows) {
      const double a = w[std::max(windows - 1, 0)], b = w[windows], c = w[windows + 1], d = w[windows + 2];
      running = std::max({running, (a + 4.0 * b + c) / 6.0, (a + 23.0 * b + 23.0 * c + d) / 48.0});
    }
    return running;
  };
  for (int s = 0; s < steps() && s != stop; ++s) {
    const double t = schedule_.distances[s];
    if (stop == steps() && m > 0) {
      const double bound = std::max(z_bound_ - h0, 0.0) / t;
      if (bound < q[steepest]) {  // necessary for both; the smooth max needs its windows
        if (!options_.smooth_max) break;
        if (std::atan(bound) + MarchExitSlack::angle <= smooth_lower_bound()) {
          stop = s + MarchExitSlack::smooth_window - 1;
        }
      }
    }
    const GridPoint p = ray_point(field_, origin, u, t);
    if (!on_grid(field_, p)) break;
    q[m] = (height_at(s, p) - options_.curvature.drop(t) - h0) / t;
    if (q[m] > q[steepest]) steepest = m;
    ++m;
  }
  if (steps_marched) *steps_marched = m;
  if (m == 0) return -std::numeric_limits<double>::infinity();
  if (!options_.smooth_max) return std::atan(q[steepest]);
  // Uniform cubic B-spline through the angles, ends replicated: max of the curve at
  // every knot and midpoint. Each is a convex combination of angles s−1 … s+2, so a
  // window whose steepest slope is ≤ tan(best) cannot raise the max: skipped, which
  // leaves the result unchanged and saves most atan calls.
  std::fill(w, w + m, std::numeric_limits<double>::quiet_NaN());
  auto slope = [&](int s) { return q[std::clamp(s, 0, m - 1)]; };
  auto angle = [&](int s) {
    s = std::clamp(s, 0, m - 1);
    if (std::isnan(w[s])) w[s] = std::atan(q[s]);
    return w[s];
  };
  double best = -std::numeric_limits<double>::infinity(), best_slope = best;
  auto visit = [&](int s) {
    if (std::max({slope(s - 1), slope(s), slope(s + 1), slope(s + 2)}) <= best_slope) return;
    const double knot = (angle(s - 1) + 4.0 * angle(s) + angle(s + 1)) / 6.0;
    const double mid = (angle(s - 1) + 23.0 * angle(s) + 23.0 * angle(s + 1) + angle(s + 2)) / 48.0;
    if (std::max(knot, mid) > best) best = std::max(knot, mid), best_slope = std::tan(best);
  };
  for (int s = std::max(0, steepest - 2); s <= std::min(m - 1, steepest + 1); ++s) visit(s);  // a good start
  for (int s = 0; s < m; ++s) visit(s);
  return best;
}

}  // namespace skylit::horizon
