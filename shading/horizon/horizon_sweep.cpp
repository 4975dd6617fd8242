#include "shading/horizon/horizon_sweep.h"

#include "shading/horizon/horizon_exact.h"
#include "shading/horizon/horizon_ray.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace skylit::horizon {

bool sweep_applicable(const terrain::HeightField& field, const MarchOptions& o) {
  return sweep_inapplicable_reason(field, o).empty();
}

std::string sweep_inapplicable_reason(const terrain::HeightField& field, const MarchOptions& o) {
  if (!one_row_spacing(field)) return "the rows' spacings differ (a geographic grid)";
  if (o.max_distance_m <= 0.0) return "";  // the DEM extent
  const double diagonal = std::hypot((field.width - 1) * field.dx(0), (field.height - 1) * field.dy);
  if (o.max_distance_m >= diagonal) return "";
  char text[128];
  std::snprintf(text, sizeof text, "the maximum distance %g m is below the DEM's diagonal %.1f m", o.max_distance_m,
                diagonal);
  return text;
}

int SweepGeometry::owner(double a, double b) const {
  return static_cast<int>(std::floor((b - r * a - c_low) * lines_per_texel + 0.5));
}

SweepGeometry sweep_geometry(const terrain::HeightField& field, Heading u, int lines_per_texel) {
  SweepGeometry g;
  const double ex = u.east / field.dx(0), ey = -u.north / field.dy;  // texels per metre along u
  g.x_dominant = std::abs(ex) >= std::abs(ey);
  const double ea = g.x_dominant ? ex : ey, eb = g.x_dominant ? ey : ex;
  g.step_m = exact_step_length(field, 0, u, 0.5);
  g.delta_a = ea > 0.0 ? 0.5 : -0.5;
  g.r = eb / ea;
  g.extent_a = g.x_dominant ? field.width : field.height;
  g.extent_b = g.x_dominant ? field.height : field.width;
  g.samples = 2 * (g.extent_a - 1) + 1;
  g.lines_per_texel = lines_per_texel;
  // c = b − r·a over the grid's corners, with a line of margin on each side.
  const double a1 = g.extent_a - 1.0, b1 = g.extent_b - 1.0;
  const double c_min = std::min({0.0, -g.r * a1, b1, b1 - g.r * a1});
  const double c_max = std::max({0.0, -g.r * a1, b1, b1 - g.r * a1});
  g.c_low = c_min - g.spacing();
  g.lines = static_cast<int>(std::ceil((c_max - g.c_low) / g.spacing())) + 2;
  return g;
}

namespace {

// Upper convex hull of the samples passed, nearest on top (Andrew's monotone chain).
// Positions n are in steps: slopes per step, divided by step_m by the caller.
class Hull {
 public:
  void clear() { n_.clear(), z_.clear(); }
  // Adds a sample nearer than every one held.
  void push(double n, double z) {
    while (n_.size() >= 2) {
      const std::size_t top = n_.size() - 1;
      // Keep top only if strictly above the chord from (n, z) to the one below it.
      if ((z_[top] - z) * (n_[top - 1] - n) > (z_[top - 1] - z) * (n_[top] - n)) break;
      n_.pop_back(), z_.pop_back();
    }
    n_.push_back(n), z_.push_back(z);
  }
  // max over the hull of (Z − z0)/(n − n0), for n0 nearer than every sample; −∞ if empty.
  double max_slope(double n0, double z0) const {
    if (n_.empty()) return -std::numeric_limits<double>::infinity();
    std::size_t k = n_.size() - 1;
    // Slopes rise then fall along a convex chain: walk away while they rise.
    while (k > 0 && (z_[k - 1] - z0) * (n_[k] - n0) >= (z_[k] - z0) * (n_[k - 1] - n0)) --k;
    return (z_[k] - z0) / (n_[k] - n0);
  }

 private:
  std::vector<double> n_, z_;
};

}  // namespace

std::uint16_t encode_far_slope(double slope) {
  if (std::isinf(slope) && slope < 0.0) return kFarCodeNone;
  const double x = std::isinf(slope) ? 1.0 : slope / (1.0 + std::abs(slope));
  const double q = kFarCodeHalfRange + std::floor(x * kFarCodeHalfRange);
  return static_cast<std::uint16_t>(std::clamp(q, 1.0, double{kFarCodeMax}));
}

float decode_far_slope(std::uint16_t code) {
  if (code == kFarCodeNone) return -std::numeric_limits<float>::infinity();
  const double x = static_cast<double>(code) / kFarCodeHalfRange - 1.0;
  return static_cast<float>(x / (1.0 - std::abs(x)));
}

std::vector<std::uint16_t> sweep_far_slopes(const terrain::HeightField& field, Heading u, const MarchOptions& o) {
  validate(o);
  if (!sweep_applicable(field, o)) throw std::invalid_argument("sweep: needs rows of one spacing and D ≥ the DEM");
  const SweepGeometry g = sweep_geometry(field, u, o.sweep_lines);
  const double drop = o.curvature.drop_per_square_metre() * g.step_m * g.step_m;  // per step²
  const double eps = edge_epsilon_texels(field);
  const int delay = o.sweep_near_steps + 1;
  std::vector<std::uint16_t> far(field.size(), kFarCodeNone);
  Hull hull;
  auto point = [&](double a, double b) { return g.x_dominant ? GridPoint{a, b} : GridPoint{b, a}; };
  for (int line = 0; line < g.lines; ++line) {
    const double c = g.c_low + line * g.spacing();
    hull.clear();
    for (int n = g.samples - 1; n >= 0; --n) {
      // The sample `delay` steps on enters the hull; Z = z − s²/(2R) (header).
      if (const int m = n + delay; m < g.samples) {
        const double a = g.a_at(m), b = c + g.r * a;
        if (b >= -eps && b <= g.extent_b - 1 + eps) hull.push(m, bilinear_height(field, point(a, b)) - m * drop * m);
      }
      if (n % 2 != 0) continue;  // observers sit on whole texels of a
      const double a = g.a_at(n), b = c + g.r * a;
      for (const double jb : {std::floor(b), std::ceil(b)}) {
        if (jb < 0.0 || jb > g.extent_b - 1 || g.owner(a, jb) != line) continue;
        const GridPoint p = point(a, jb);
        const int i = static_cast<int>(p.x), j = static_cast<int>(p.y);
        // tan = (Z − H₀)/t + s₀/R_eff, per step: ÷ step_m; s₀/R_eff = 2·n·drop/step_m.
        const double slope = hull.max_slope(n, field.at(i, j) - n * drop * n);
        far[static_cast<std::size_t>(j) * field.width + i] = encode_far_slope((slope + 2.0 * n * drop) / g.step_m);
      }
    }
  }
  return far;
}

double sweep_max_elevation(const terrain::HeightField& field, int i, int j, Heading u, std::uint16_t far_code,
                           const MarchOptions& o) {
  const double h0 = field.at(i, j);
  const double step = exact_step_length(field, j, u, 0.5);
  double best = -std::numeric_limits<double>::infinity();
  // The first step is checked even without near steps: a ray leaving the grid there has
  // no horizon (−∞), whatever the owner line beside it sees.
  for (int k = 1; k <= std::max(o.sweep_near_steps, 1); ++k) {
    const double t = k * step;
    const GridPoint p = ray_point(field, i, j, u, t);
    if (!on_grid(field, p)) return std::isinf(best) ? best : std::atan(best);  // no far field
    if (k <= o.sweep_near_steps) best = std::max(best, (bilinear_height(field, p) - o.curvature.drop(t) - h0) / t);
  }
  best = std::max(best, static_cast<double>(decode_far_slope(far_code)));
  return std::isinf(best) ? best : std::atan(best);
}

}  // namespace skylit::horizon
