#include "shading/horizon/horizon_sweep.h"

#include "shading/horizon/horizon_exact.h"
#include "shading/horizon/horizon_ray.h"
#include "shading/horizon/horizon_subsample.h"
#include "parallel/parallel_rows.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <vector>

namespace skylit::horizon {

bool sweep_applicable(const terrain::HeightField& field, const MarchOptions& o) {
  return sweep_inapplicable_reason(field, o).empty();
}

std::string sweep_inapplicable_reason(const terrain::HeightField& field, const MarchOptions& o) {
  const auto [lo, hi] = std::minmax_element(field.dx_per_row.begin(), field.dx_per_row.end());
  char text[160];
  if (*hi > kMaxRowSpacingRatio * *lo) {
    std::snprintf(text, sizeof text, "the rows' east–west spacings differ more than %g× (%.3g … %.3g m: near a pole)",
                  kMaxRowSpacingRatio, *lo, *hi);
    return text;
  }
  if (!sweep_bounded(field, o)) return "";
  // The near steps come from each texel's own ray, which does not stop at the distance.
  const double longest_step = 0.5 * std::hypot(*hi, field.dy);
  if (o.max_distance_m < (o.sweep_near_steps + 1) * longest_step) {
    std::snprintf(text, sizeof text, "the maximum distance %g m is within the %d near steps (%.3g m)", o.max_distance_m,
                  o.sweep_near_steps, (o.sweep_near_steps + 1) * longest_step);
    return text;
  }
  return "";
}

bool sweep_bounded(const terrain::HeightField& field, const MarchOptions& o) {
  if (o.max_distance_m <= 0.0) return false;  // the DEM extent
  const double widest = *std::max_element(field.dx_per_row.begin(), field.dx_per_row.end());
  return o.max_distance_m < std::hypot((field.width - 1) * widest, (field.height - 1) * field.dy);
}

double sweep_window_steps(const terrain::HeightField& field, const SweepGeometry& g, const MarchOptions& o) {
  if (!sweep_bounded(field, o)) return std::numeric_limits<double>::infinity();
  return o.max_distance_m * (1.0 + 1e-12) / g.step_m;  // the exact march stops at t > D·(1 + 1e-12)
}

double SweepGeometry::line_c(double a, double b) const {
  if (!curved()) return b - r * a;
  return x_dominant ? rows->gamma(b) - r * a : b - r * rows->gamma(a);
}

int SweepGeometry::owner(double a, double b) const {
  return static_cast<int>(std::floor((line_c(a, b) - c_low) * lines_per_texel + 0.5));
}

SweepGeometry sweep_geometry(const terrain::HeightField& field, Heading u, int lines_per_texel,
                             std::shared_ptr<const RhumbRows> rows) {
  SweepGeometry g;
  if (!one_row_spacing(field)) g.rows = rows ? std::move(rows) : std::make_shared<const RhumbRows>(field);
  const double dx = g.curved() ? g.rows->d_ref() : field.dx(0);
  const double ex = u.east / dx, ey = -u.north / field.dy;  // texels per metre along u
  g.x_dominant = std::abs(ex) >= std::abs(ey);
  const double ea = g.x_dominant ? ex : ey, eb = g.x_dominant ? ey : ex;
  g.step_m = g.curved() ? 0.5 / std::max(std::abs(ex), std::abs(ey)) : exact_step_length(field, 0, u, 0.5);
  g.delta_a = ea > 0.0 ? 0.5 : -0.5;
  g.r = eb / ea;
  g.extent_a = g.x_dominant ? field.width : field.height;
  g.extent_b = g.x_dominant ? field.height : field.width;
  g.samples = 2 * (g.extent_a - 1) + 1;
  g.lines_per_texel = lines_per_texel;
  // c = b − r·a over the grid's corners (the row axis in Γ), with a line of margin on each side.
  double a1 = g.extent_a - 1.0, b1 = g.extent_b - 1.0;
  if (g.curved()) (g.x_dominant ? b1 : a1) = g.rows->last();
  const double c_min = std::min({0.0, -g.r * a1, b1, b1 - g.r * a1});
  const double c_max = std::max({0.0, -g.r * a1, b1, b1 - g.r * a1});
  // Lines on the lattice c = k·spacing of the raster the grid is a window of (one row
  // spacing: the window's c is the raster's less b₀ − r·a₀), so that windows cut from one
  // raster sweep the same lines; the phase is taken modulo the spacing to keep c small.
  double phase = 0.0;
  if (!g.curved()) {
    const double a0 = g.x_dominant ? field.origin_column : field.origin_row;
    const double b0 = g.x_dominant ? field.origin_row : field.origin_column;
    phase = b0 - g.r * a0;
    phase -= std::floor(phase / g.spacing()) * g.spacing();
  }
  g.c_low = (std::floor((c_min + phase) / g.spacing()) - 1.0) * g.spacing() - phase;
  g.lines = static_cast<int>(std::ceil((c_max - g.c_low) / g.spacing())) + 2;
  return g;
}

namespace {

// Upper convex hull of the samples passed, nearest on top (Andrew's monotone chain).
// Positions n are in steps: slopes per step, divided by step_m by the caller. Vertices
// live in one buffer sized for a whole line (reserve), so a push is no allocation.
class Hull {
 public:
  void reserve(std::size_t samples) {
    if (v_.size() < samples) v_.resize(samples);
  }
  void clear() { size_ = 0; }
  // Adds a sample nearer than every one held (at most `reserve`d of them).
  void push(double n, double z) {
    while (size_ >= 2) {
      const Vertex& top = v_[size_ - 1];
      const Vertex& below = v_[size_ - 2];
      // Keep top only if strictly above the chord from (n, z) to the one below it.
      if ((top.z - z) * (below.n - n) > (below.z - z) * (top.n - n)) break;
      --size_;
    }
    v_[size_++] = {n, z};
  }
  // max over the hull of (Z − z0)/(n − n0), for n0 nearer than every sample; −∞ if empty.
  double max_slope(double n0, double z0) const {
    if (size_ == 0) return -std::numeric_limits<double>::infinity();
    std::size_t k = size_ - 1;
    // Slopes rise then fall along a convex chain: walk away while they rise.
    while (k > 0 && (v_[k - 1].z - z0) * (v_[k].n - n0) >= (v_[k].z - z0) * (v_[k - 1].n - n0)) --k;
    return (v_[k].z - z0) / (v_[k].n - n0);
  }

 private:
  struct Vertex {
    double n, z;
  };
  std::vector<Vertex> v_;
  std::size_t size_ = 0;
};

// Upper convex hull of a run of samples that loses its farthest one as the search's far
// end passes it: built from the nearest sample outwards, each push remembers the
// vertices it hid, so that popping the farthest sample restores them.
class FarHull {
 public:
  void clear() { n_.clear(), z_.clear(), hidden_n_.clear(), hidden_z_.clear(), hid_.clear(); }
  bool empty() const { return hid_.empty(); }
  // Adds a sample farther than every one held.
  void push_far(double n, double z) {
    int hid = 0;
    while (n_.size() >= 2) {
      const std::size_t top = n_.size() - 1;
      // Keep top only if strictly above the chord from the one before it to (n, z).
      if ((z_[top] - z) * (n_[top - 1] - n) < (z_[top - 1] - z) * (n_[top] - n)) break;
      hidden_n_.push_back(n_[top]), hidden_z_.push_back(z_[top]);
      n_.pop_back(), z_.pop_back(), ++hid;
    }
    n_.push_back(n), z_.push_back(z), hid_.push_back(hid);
  }
  // Removes the last sample pushed (the farthest held).
  void pop_far() {
    n_.pop_back(), z_.pop_back();
    for (int k = hid_.back(); k > 0; --k) {
      n_.push_back(hidden_n_.back()), z_.push_back(hidden_z_.back());
      hidden_n_.pop_back(), hidden_z_.pop_back();
    }
    hid_.pop_back();
  }
  // max over the hull of (Z − z0)/(n − n0), for n0 nearer than every sample (not empty):
  // the slopes rise then fall from the nearest vertex, so bisect for the turn.
  double max_slope(double n0, double z0) const {
    std::size_t lo = 0, hi = n_.size() - 1;
    while (lo < hi) {
      const std::size_t mid = (lo + hi) / 2;
      if ((z_[mid + 1] - z0) * (n_[mid] - n0) >= (z_[mid] - z0) * (n_[mid + 1] - n0)) lo = mid + 1;
      else hi = mid;
    }
    return (z_[lo] - z0) / (n_[lo] - n0);
  }

 private:
  std::vector<double> n_, z_;                 // nearest first
  std::vector<double> hidden_n_, hidden_z_;  // the vertices pushes hid, last hidden on top
  std::vector<int> hid_;                      // per push, how many it hid
};

// The samples within `limit` steps of the observer, as a queue that gains the nearest
// and loses the farthest: the hull of the newest (Hull) and that of the older ones
// (FarHull), which takes all of them over when its own run is used up, so every sample
// is pushed at most twice. An infinite limit (no bound) keeps the newest hull alone.
struct WindowHulls {
  double limit = std::numeric_limits<double>::infinity();
  Hull near;
  FarHull far;
  std::vector<double> n, z;    // the samples entered while bounded, farthest first
  std::size_t first = 0;       // the farthest one still within the distance
  std::size_t split = 0;       // samples [first, split) are far's, [split, end) near's
  void clear() { near.clear(), far.clear(), n.clear(), z.clear(), first = split = 0; }
  void push(double pn, double pz) {
    near.push(pn, pz);
    if (std::isfinite(limit)) n.push_back(pn), z.push_back(pz);
  }
  // Drops the samples farther than `limit` steps from n0.
  void expire(double n0) {
    while (first < n.size() && n[first] - n0 > limit) {
      if (first == split) {  // far is used up: it takes over near's samples
        far.clear();
        for (std::size_t k = n.size(); k-- > first;) far.push_far(n[k], z[k]);
        near.clear();
        split = n.size();
      }
      far.pop_far(), ++first;
    }
  }
  double max_slope(double n0, double z0) const {
    const double s = near.max_slope(n0, z0);
    return far.empty() ? s : std::max(s, far.max_slope(n0, z0));
  }
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

namespace {

// Sample n of line c: its cross coordinate b (texels) and its position p along the line
// in steps of step_m (the hull's abscissa; p = n unless the columns lead on a curved grid).
struct LineSamples {
  std::vector<double> b, p;
};

void fill_line(const SweepGeometry& g, double c, LineSamples& out) {
  out.b.resize(g.samples);
  out.p.resize(g.samples);
  for (int n = 0; n < g.samples; ++n) out.p[n] = n;
  if (!g.curved()) {
    for (int n = 0; n < g.samples; ++n) out.b[n] = c + g.r * g.a_at(n);
    return;
  }
  const RhumbRows& rows = *g.rows;
  if (!g.x_dominant) {  // samples on half rows: Γ from the table, b = c + r·Γ(a)
    const std::vector<double>& half = rows.half_rows();
    for (int n = 0; n < g.samples; ++n) out.b[n] = c + g.r * half[static_cast<std::size_t>(2.0 * g.a_at(n))];
    return;
  }
  // Samples on half columns: b = Γ⁻¹(c + r·a). Along the line dΓ = D_ref·dy/D, so the
  // east metres are ∫D dx = D_ref·Δy/r and the position p = s/step_m = Δy/(r·δ_a), exact
  // for the rows' linear spacing; within 1e-6 of due east the line keeps its row and
  // p = n·D(b₀)/D_ref (the neglected change of D is below 1e-6·W rows).
  int segment = 0;
  for (int n = 0; n < g.samples; ++n) out.b[n] = rows.row(c + g.r * g.a_at(n), segment);
  if (std::abs(g.r) < kDueEastSlope) {
    const double scale = rows.dx(out.b[0]) / rows.d_ref();
    for (int n = 0; n < g.samples; ++n) out.p[n] = n * scale;
    return;
  }
  for (int n = 0; n < g.samples; ++n) out.p[n] = (out.b[n] - out.b[0]) / (g.r * g.delta_a);
}

// The lines owning a wanted texel and the samples where wanted observers sit (all of
// them for an empty region): owner() and a_at() are monotone in each coordinate, so the
// region's corners bound both.
struct Wanted {
  int line_low = 0, line_high = -1;
  int n_low = 0, n_high = -1;
};

Wanted wanted_lines(const terrain::HeightField& field, const SweepGeometry& g, const terrain::PixelRect& region) {
  terrain::PixelRect r = region.empty() ? field.bounds() : region;
  r.width = std::min(r.x1(), field.width) - r.x0;
  r.height = std::min(r.y1(), field.height) - r.y0;
  Wanted w;
  if (r.empty()) return w;
  w.line_low = g.lines - 1;
  w.line_high = 0;
  w.n_low = g.samples - 1;
  w.n_high = 0;
  for (const int i : {r.x0, r.x1() - 1})
    for (const int j : {r.y0, r.y1() - 1}) {
      const double a = g.x_dominant ? i : j, b = g.x_dominant ? j : i;
      const int line = std::clamp(g.owner(a, b), 0, g.lines - 1);
      w.line_low = std::min(w.line_low, line);
      w.line_high = std::max(w.line_high, line);
      const int n = static_cast<int>(std::lround((a - g.a_at(0)) / g.delta_a));
      w.n_low = std::min(w.n_low, n);
      w.n_high = std::max(w.n_high, n);
    }
  return w;
}

// Each texel's 3 × 3 neighbourhood's highest height (clamped at the edges): no bilinear
// sample within one texel of it rises higher. Rows spread over `threads`, as the sweep's
// lines: it runs before every floored sweep (≈ 6 ms on one core at 1024²).
std::vector<float> neighbourhood_max(const terrain::HeightField& field, unsigned threads) {
  const int w = field.width, h = field.height;
  std::vector<float> across(field.size()), out(field.size());
  parallel::parallel_rows(h, threads, [&](int j) {
    for (int i = 0; i < w; ++i)
      across[static_cast<std::size_t>(j) * w + i] =
          std::max({field.at(std::max(i - 1, 0), j), field.at(i, j), field.at(std::min(i + 1, w - 1), j)});
  });
  parallel::parallel_rows(h, threads, [&](int j) {
    const float* up = &across[static_cast<std::size_t>(std::max(j - 1, 0)) * w];
    const float* mid = &across[static_cast<std::size_t>(j) * w];
    const float* down = &across[static_cast<std::size_t>(std::min(j + 1, h - 1)) * w];
    float* row = &out[static_cast<std::size_t>(j) * w];
    for (int i = 0; i < w; ++i) row[i] = std::max({up[i], mid[i], down[i]});
  });
  return out;
}

// An observer of a line whose far slope may reach the floor (floored sweeps): its sample
// index n and texel.
struct Observer {
  int n = 0;
  std::size_t texel = 0;
  double reach = 0.0;  // the last loop index n whose entering sample (n + delay) may lift it to the floor
};

}  // namespace

std::vector<std::uint16_t> sweep_far_slopes(const terrain::HeightField& field, Heading u, const MarchOptions& o,
                                            unsigned threads, double floor_slope, int observer_step) {
  validate(o);
  if (const std::string why = sweep_inapplicable_reason(field, o); !why.empty())
    throw std::invalid_argument("sweep: " + why);
  if (observer_step < 1) throw std::invalid_argument("sweep: the observer step must be at least 1");
  const SubsampleAxis observer_columns{field.width, observer_step}, observer_rows{field.height, observer_step};
  const SweepGeometry g = sweep_geometry(field, u, o.sweep_lines);
  const double drop = o.curvature.drop_per_square_metre() * g.step_m * g.step_m;  // per step²
  const double eps = edge_epsilon_texels(field);
  const int delay = o.sweep_near_steps + 1;
  std::vector<std::uint16_t> far(field.size(), kFarCodeNone);
  auto point = [&](double a, double b) { return g.x_dominant ? GridPoint{a, b} : GridPoint{b, a}; };
  // A bounded search: samples farther than D from the observer leave the window,
  // t = (p − p₀)·step_m.
  const double window_steps = sweep_window_steps(field, g, o);
  const Wanted wanted = wanted_lines(field, g, o.region);
  // A texel is a line's only if its c is within spacing/2 of the line's (owner()), with
  // room for the rounding of b and c. In texels of b that is as far on straight lines;
  // where b is a row of a curved grid, Γ stretches rows by D_ref/D ≥ D_ref/D_max, so a
  // texel within reach in Γ is within reach·D_max/D_ref rows, and a line may own two.
  const double owner_reach = 0.5 * g.spacing() + 1e-6;
  const bool stretched_rows = g.curved() && g.x_dominant;
  const double reach =
      stretched_rows ? owner_reach * *std::max_element(field.dx_per_row.begin(), field.dx_per_row.end()) / g.rows->d_ref()
                     : owner_reach;
  // The floor (per step): an observer whose far samples all stay below the line of that
  // slope from it is left kFarCodeNone, or gets the max over fewer samples (header).
  // Without the curvature's drop a slope only rises (true slope = plain slope − drop·t),
  // and a sample's height is at most the 3 × 3 maximum around the whole-texel sample
  // beside it. Straight lines only, where a sample's position is its index.
  const double floor_step = floor_slope * g.step_m;
  const bool floored = floor_step > 0.0 && std::isfinite(floor_step) && !g.curved() && drop >= 0.0;
  const std::vector<float> box = floored ? neighbourhood_max(field, threads) : std::vector<float>();
  auto index = [&](int i, int j) { return static_cast<std::size_t>(j) * field.width + i; };
  // A line writes only the texels it owns, so lines run on any thread in any order.
  auto sweep_line = [&](int line, WindowHulls& hulls, LineSamples& line_samples, std::vector<Observer>& open) {
    const double c = g.c_low + line * g.spacing();
    fill_line(g, c, line_samples);
    const std::vector<double>&bs = line_samples.b, &ps = line_samples.p;
    hulls.clear();
    // Observers n_low … n_high are wanted; they see samples up to the window's length
    // past n_high (all of them unbounded), which enter the hull `delay` steps earlier.
    int top = g.samples - 1;
    if (std::isfinite(window_steps)) {
      int last = wanted.n_high;
      while (last + 1 < g.samples && ps[last + 1] - ps[wanted.n_high] <= window_steps) ++last;
      top = std::min(top, std::max(wanted.n_high, last - delay));
    }
    // b is monotone along a line: only the run of samples beside the grid (b within a
    // texel of it) holds observers or samples; it starts `delay` steps earlier for pushes.
    auto beside = [&](int n) { return bs[n] > -1.0 - 1e-6 && bs[n] < g.extent_b + 1e-6; };
    int beside_low = 0, beside_high = g.samples - 1;
    while (beside_low < g.samples && !beside(beside_low)) ++beside_low;
    if (beside_low == g.samples) return;  // the line misses the grid
    while (!beside(beside_high)) --beside_high;
    top = std::min(top, beside_high);
    const int bottom = std::max(wanted.n_low, beside_low - delay);
    // The texels this line owns at observer sample n (whole texels of a), the nearer to
    // the line first: most are settled by `reach` without owner().
    auto for_owned = [&](int n, auto&& visit) {
      const double a = g.a_at(n), b = bs[n];
      const double nearest = std::floor(b + 0.5);
      const double other = b < nearest ? nearest - 1.0 : nearest + 1.0;
      for (const double jb : {nearest, other}) {
        if (jb == other && b == nearest) break;  // b whole: one texel beside it
        if (std::abs(jb - b) > reach) break;
        if (jb < 0.0 || jb > g.extent_b - 1 || g.owner(a, jb) != line) continue;
        const GridPoint q = point(a, jb);
        if (observer_step == 1 ||
            (observer_columns.coarse(static_cast<int>(q.x)) && observer_rows.coarse(static_cast<int>(q.y))))
          visit(static_cast<int>(q.x), static_cast<int>(q.y));
        if (!stretched_rows) break;  // one texel at most
      }
    };
    auto observe = [&](int n, int i, int j) {
      const double pn = ps[n];
      hulls.expire(pn);
      // tan = (Z − H₀)/t + s₀/R_eff, per step: ÷ step_m; s₀/R_eff = 2·p·drop/step_m.
      const double slope = hulls.max_slope(pn, field.at(i, j) - pn * drop * pn);
      far[static_cast<std::size_t>(j) * field.width + i] = encode_far_slope((slope + 2.0 * pn * drop) / g.step_m);
    };
    // The sample `delay` steps on from n enters the hull; Z = z − s²/(2R) (header).
    auto enter = [&](int n) {
      if (const int m = n + delay; m < g.samples) {
        const double b = bs[m];
        if (b >= -eps && b <= g.extent_b - 1 + eps) hulls.push(ps[m], bilinear_height(field, point(g.a_at(m), b)) - ps[m] * drop * ps[m]);
      }
    };
    if (!floored) {
      for (int n = top; n >= bottom; --n) {
        enter(n);
        if (n % 2 == 0 && n <= wanted.n_high) for_owned(n, [&](int i, int j) { observe(n, i, j); });
      }
      return;
    }
    // Floored: first the observers whose far slope may reach the floor. The samples
    // m' − 1 … m' + 1 around a whole-texel sample m' (even) lie within a texel of it and
    // at positions ≥ m' − 1, so z_m − s·(m − n) ≤ box(m') − s·(m' − 1 − n); the observer
    // at n is settled when the largest box(m') − s·m' over m' ≥ n + delay − 1 stays
    // below h − s·(n + 1), less a rounding slack.
    open.clear();
    double bound = -std::numeric_limits<double>::infinity();  // max of box(m') − s·m'
    double peak = -std::numeric_limits<double>::infinity();   // max of box(m')
    int next = std::min(top + delay + 1, g.samples - 1);
    next -= next % 2;
    for (int n = top - top % 2; n >= bottom; n -= 2) {
      for (; next >= std::max(n + delay - 1, 0); next -= 2) {
        const double b = bs[next];
        if (b < -1.0 || b > g.extent_b) continue;  // no sample beside it is pushed
        const int ia = static_cast<int>(g.a_at(next));
        const int ib = std::clamp(static_cast<int>(std::floor(b)), 0, g.extent_b - 1);
        const int ib1 = std::min(ib + 1, g.extent_b - 1);
        const double high = g.x_dominant ? std::max(box[index(ia, ib)], box[index(ia, ib1)])
                                         : std::max(box[index(ib, ia)], box[index(ib1, ia)]);
        bound = std::max(bound, high - floor_step * next);
        peak = std::max(peak, high);
      }
      if (n > wanted.n_high) continue;
      for_owned(n, [&](int i, int j) {
        const double h = field.at(i, j);
        if (bound + floor_step * (n + 1) < h - 1e-9 * (1.0 + std::abs(h))) return;  // below the floor
        // Samples more than (peak − h)/s past n (+ 1 for the positions' slack, + 1 to
        // spare) stay under its floor line: only those before may enter for it.
        open.push_back({n, index(i, j), n + (peak - h) / floor_step + 2.0});
      });
    }
    if (open.empty()) return;
    // Then the hull for those alone, and of the samples only those some open observer
    // below may need: sample n + delay enters while the farthest reach of the open
    // observers at or below n is at least n.
    for (std::size_t q = open.size() - 1; q-- > 0;) open[q].reach = std::max(open[q].reach, open[q + 1].reach);
    std::size_t k = 0;  // open[k]: the first open observer at or below n (descending)
    for (int n = static_cast<int>(std::min<double>(top, std::floor(open.front().reach))); n >= open.back().n; --n) {
      while (k < open.size() && open[k].n > n) ++k;
      if (k == open.size()) break;
      if (open[k].reach < n) {  // nothing open below needs this sample: skip ahead
        n = static_cast<int>(std::floor(open[k].reach)) + 1;
        continue;
      }
      enter(n);
      for (std::size_t q = k; q < open.size() && open[q].n == n; ++q)
        observe(n, static_cast<int>(open[q].texel % field.width), static_cast<int>(open[q].texel / field.width));
    }
  };
  constexpr int kLinesPerTask = 32;  // a task's hull and samples serve its lines
  const int lines = wanted.line_high - wanted.line_low + 1;
  parallel::parallel_rows((lines + kLinesPerTask - 1) / kLinesPerTask, threads, [&](int t) {
    WindowHulls hulls;
    hulls.limit = window_steps;
    hulls.near.reserve(static_cast<std::size_t>(g.samples));
    LineSamples line_samples;
    std::vector<Observer> open;
    const int first = wanted.line_low + t * kLinesPerTask;
    for (int line = first; line < std::min(wanted.line_high + 1, first + kLinesPerTask); ++line)
      sweep_line(line, hulls, line_samples, open);
  });
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
