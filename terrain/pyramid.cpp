#include "terrain/pyramid.h"

#include "parallel/parallel_rows.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <thread>

namespace skylit::terrain {
namespace {

// Centred cubic B-spline β3, support [−2, 2].
double bspline3(double t) {
  t = std::abs(t);
  if (t < 1.0) return (4.0 - 6.0 * t * t + 3.0 * t * t * t) / 6.0;
  if (t < 2.0) {
    const double u = 2.0 - t;
    return u * u * u / 6.0;
  }
  return 0.0;
}

using Taps = ReductionTaps;

// w_k = ∫ hat(x − k) β3((p − x)/s)/s dx, with the hat (linear interpolation) basis of
// the input. The integrand is a polynomial of degree ≤ 4 between the knots of both
// factors, so 3-point Gauss–Legendre on each piece is exact.
Taps reduction_taps(double p, double s) {
  static const double gx[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  static const double gw[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  Taps taps;
  const int k0 = static_cast<int>(std::floor(p - 2.0 * s)) - 1;
  const int k1 = static_cast<int>(std::ceil(p + 2.0 * s)) + 1;
  taps.first = k0;
  for (int k = k0; k <= k1; ++k) {
    std::vector<double> knots = {k - 1.0, double(k), k + 1.0};
    for (int m = -2; m <= 2; ++m) {
      const double x = p + m * s;
      if (x > k - 1.0 && x < k + 1.0) knots.push_back(x);
    }
    std::sort(knots.begin(), knots.end());
    double w = 0.0;
    for (std::size_t q = 0; q + 1 < knots.size(); ++q) {
      const double a = knots[q], b = knots[q + 1], h = 0.5 * (b - a), c = 0.5 * (a + b);
      for (int g = 0; g < 3; ++g) {
        const double x = c + h * gx[g];
        w += gw[g] * h * std::max(0.0, 1.0 - std::abs(x - k)) * bspline3((p - x) / s) / s;
      }
    }
    taps.weight.push_back(w);
  }
  return taps;
}

// Range [lo, hi) of outputs whose (clamped) taps touch inputs [in_lo, in_hi).
std::pair<int, int> affected(const std::vector<Taps>& taps, int n_in, int in_lo, int in_hi) {
  int lo = static_cast<int>(taps.size()), hi = 0;
  for (int i = 0; i < static_cast<int>(taps.size()); ++i) {
    const int a = std::clamp(taps[i].first, 0, n_in - 1);
    const int b = std::clamp(taps[i].first + static_cast<int>(taps[i].weight.size()) - 1, 0, n_in - 1);
    if (a < in_hi && b >= in_lo) lo = std::min(lo, i), hi = std::max(hi, i + 1);
  }
  return {lo, std::max(lo, hi)};
}

// Solves the B-spline interpolation system (bspline_factors) in place over n values
// spaced `stride` apart; d is scratch.
void bspline_solve(float* f, int n, std::size_t stride, const BSplineFactors& lu, std::vector<double>& d) {
  if (n == 1) return;  // the clamped system is c = f
  d.resize(n);
  const double off = kBSplineOffDiagonal;
  d[0] = f[0] / lu.pivot[0];
  for (int i = 1; i < n; ++i) d[i] = (f[i * stride] - off * d[i - 1]) / lu.pivot[i];
  f[(n - 1) * stride] = static_cast<float>(d[n - 1]);
  double next = d[n - 1];
  for (int i = n - 2; i >= 0; --i) {
    next = d[i] - lu.upper[i] * next;
    f[i * stride] = static_cast<float>(next);
  }
}

void compute_coeffs(PyramidLevel& lv) {
  lv.coeffs = lv.samples;
  std::vector<double> d;
  const BSplineFactors rows = bspline_factors(lv.width), cols = bspline_factors(lv.height);
  for (int j = 0; j < lv.height; ++j)
    bspline_solve(lv.coeffs.data() + static_cast<std::size_t>(j) * lv.width, lv.width, 1, rows, d);
  for (int i = 0; i < lv.width; ++i) bspline_solve(lv.coeffs.data() + i, lv.height, lv.width, cols, d);
}

double clamp_coord(double v, int n) {
  if (!(v > 0.0)) return 0.0;  // also NaN
  return std::min(v, static_cast<double>(n - 1));
}

void bspline_weights(double t, double w[4]) {
  const double t2 = t * t, t3 = t2 * t;
  w[0] = (1.0 - t) * (1.0 - t) * (1.0 - t) / 6.0;
  w[1] = (3.0 * t3 - 6.0 * t2 + 4.0) / 6.0;
  w[2] = (-3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0) / 6.0;
  w[3] = t3 / 6.0;
}

// Runs f(a, b) over [lo, hi) in one chunk per hardware thread when the work is large
// enough to pay for the threads.
template <class F>
void in_row_chunks(int lo, int hi, std::size_t work_per_row, F&& f) {
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t total = work_per_row * static_cast<std::size_t>(std::max(0, hi - lo));
  const int n = static_cast<int>(std::min<std::size_t>({hw, total / 200000 + 1, static_cast<std::size_t>(std::max(1, hi - lo))}));
  if (n <= 1) return f(lo, hi);
  const int chunk = (hi - lo + n - 1) / n;
  parallel::parallel_rows((hi - lo + chunk - 1) / chunk, static_cast<unsigned>(n),
                          [&](int c) { f(lo + c * chunk, std::min(hi, lo + (c + 1) * chunk)); });
}

int level_size(int n0, double scale) { return std::max(1, static_cast<int>(std::lround(n0 / scale))); }

}  // namespace

float sample_bilinear(const PyramidLevel& lv, double x, double y) {
  x = clamp_coord(x, lv.width);
  y = clamp_coord(y, lv.height);
  const int i0 = std::min(static_cast<int>(x), std::max(lv.width - 2, 0));
  const int j0 = std::min(static_cast<int>(y), std::max(lv.height - 2, 0));
  const int i1 = std::min(i0 + 1, lv.width - 1), j1 = std::min(j0 + 1, lv.height - 1);
  const double tx = x - i0, ty = y - j0;
  const double top = (1 - tx) * lv.sample_at(i0, j0) + tx * lv.sample_at(i1, j0);
  const double bottom = (1 - tx) * lv.sample_at(i0, j1) + tx * lv.sample_at(i1, j1);
  return static_cast<float>((1 - ty) * top + ty * bottom);
}

float sample_bspline(const PyramidLevel& lv, double x, double y) {
  x = clamp_coord(x, lv.width);
  y = clamp_coord(y, lv.height);
  const int i = static_cast<int>(std::floor(x)), j = static_cast<int>(std::floor(y));
  double wx[4], wy[4];
  bspline_weights(x - i, wx);
  bspline_weights(y - j, wy);
  double sum = 0.0;
  for (int b = 0; b < 4; ++b) {
    const int jj = std::clamp(j - 1 + b, 0, lv.height - 1);
    const float* row = lv.coeffs.data() + static_cast<std::size_t>(jj) * lv.width;
    double r = 0.0;
    for (int a = 0; a < 4; ++a) r += wx[a] * row[std::clamp(i - 1 + a, 0, lv.width - 1)];
    sum += wy[b] * r;
  }
  return static_cast<float>(sum);
}

std::vector<ReductionTaps> reduction_axis_taps(int n_in, int n_out) {
  if (n_in < 1 || n_out < 1) throw std::invalid_argument("pyramid: axis sizes must be ≥ 1");
  const double s = static_cast<double>(n_in) / n_out;
  std::vector<Taps> taps(n_out);
  for (int i = 0; i < n_out; ++i) taps[i] = reduction_taps((i + 0.5) * s - 0.5, s);
  return taps;
}

BSplineFactors bspline_factors(int n) {
  if (n < 1) throw std::invalid_argument("pyramid: B-spline system size must be ≥ 1");
  BSplineFactors lu;
  lu.pivot.resize(n);
  lu.upper.resize(n);
  if (n == 1) {  // c[−1] = c[0] = c[1]: (1 + 4 + 1)/6 = 1
    lu.pivot[0] = 1.0, lu.upper[0] = 0.0;
    return lu;
  }
  auto diag = [n](int i) { return (i == 0 || i == n - 1) ? 5.0 / 6.0 : 4.0 / 6.0; };  // clamped ends
  const double off = kBSplineOffDiagonal;
  for (int i = 0; i < n; ++i) {
    lu.pivot[i] = diag(i) - (i > 0 ? off * lu.upper[i - 1] : 0.0);
    lu.upper[i] = off / lu.pivot[i];
  }
  return lu;
}

int pyramid_level_count(int width, int height, const PyramidOptions& options) {
  if (options.levels < 0 || options.levels > 1024) throw std::invalid_argument("pyramid: levels must be 0…1024");
  return options.levels > 0 ? options.levels : auto_pyramid_levels(width, height, options);
}

LevelShape pyramid_level_shape(int width, int height, int k_v, int l) {
  if (k_v < 1) throw std::invalid_argument("pyramid: k_v must be at least 1");
  LevelShape shape;
  const double s = std::exp2(static_cast<double>(l) / k_v);
  shape.width = l == 0 ? width : level_size(width, s);
  shape.height = l == 0 ? height : level_size(height, s);
  shape.step_x = static_cast<double>(width) / shape.width;
  shape.step_y = static_cast<double>(height) / shape.height;
  return shape;
}

int auto_pyramid_levels(int width, int height, const PyramidOptions& o) {
  if (o.k_v < 1) throw std::invalid_argument("pyramid: k_v must be at least 1");
  if (o.min_size < 1) throw std::invalid_argument("pyramid: min_size must be at least 1");
  int n = 1;
  while (n < 1024) {
    const double s = std::exp2(static_cast<double>(n) / o.k_v);
    if (std::min(level_size(width, s), level_size(height, s)) < o.min_size) break;
    ++n;
  }
  return n;
}

HeightPyramid::HeightPyramid(const HeightField& field, const PyramidOptions& options) { build(field, options); }

double HeightPyramid::nominal_scale(int l) const { return std::exp2(static_cast<double>(l) / options_.k_v); }

void HeightPyramid::build(const HeightField& field, const PyramidOptions& options) {
  if (options.k_v < 1) throw std::invalid_argument("pyramid: k_v must be at least 1");
  if (options.levels < 0 || options.levels > 1024) throw std::invalid_argument("pyramid: levels must be 0…1024");
  if (field.width < 1 || field.height < 1 ||
      field.heights.size() != static_cast<std::size_t>(field.width) * field.height ||
      static_cast<int>(field.dx_per_row.size()) != field.height)
    throw std::invalid_argument("pyramid: malformed height field");
  options_ = options;
  const int n = pyramid_level_count(field.width, field.height, options);
  levels_.assign(n, {});
  for (int l = 0; l < n; ++l) {
    PyramidLevel& lv = levels_[l];
    const LevelShape shape = pyramid_level_shape(field.width, field.height, options.k_v, l);
    lv.width = shape.width;
    lv.height = shape.height;
    lv.step_x = shape.step_x;
    lv.step_y = shape.step_y;
    lv.dy = lv.step_y * field.dy;
    lv.dx_per_row.resize(lv.height);
    for (int j = 0; j < lv.height; ++j) {  // level-0 dx at the row's centre, interpolated
      const double y0 = clamp_coord((j + 0.5) * lv.step_y - 0.5, field.height);
      const int a = static_cast<int>(y0), b = std::min(a + 1, field.height - 1);
      lv.dx_per_row[j] = lv.step_x * ((1 - (y0 - a)) * field.dx_per_row[a] + (y0 - a) * field.dx_per_row[b]);
    }
    lv.samples.assign(static_cast<std::size_t>(lv.width) * lv.height, 0.0f);
    compute_level(field, l, field.bounds());
  }
  width_ = field.width;
  height_ = field.height;
  revision_ = field.revision;
  built_ = true;
}

void HeightPyramid::compute_level(const HeightField& field, int l, const PixelRect& region) {
  PyramidLevel& lv = levels_[l];
  if (l == 0) {
    for (int j = region.y0; j < region.y1(); ++j)
      std::copy_n(field.heights.begin() + static_cast<std::ptrdiff_t>(j) * field.width + region.x0, region.width,
                  lv.samples.begin() + static_cast<std::ptrdiff_t>(j) * lv.width + region.x0);
    compute_coeffs(lv);
    return;
  }
  const auto tx = reduction_axis_taps(field.width, lv.width);
  const auto ty = reduction_axis_taps(field.height, lv.height);
  const auto [i_lo, i_hi] = affected(tx, field.width, region.x0, region.x1());
  const auto [j_lo, j_hi] = affected(ty, field.height, region.y0, region.y1());
  if (i_lo >= i_hi || j_lo >= j_hi) return;
  // Level-0 rows the affected outputs read.
  int r_lo = field.height, r_hi = 0;
  for (int j = j_lo; j < j_hi; ++j) {
    r_lo = std::min(r_lo, std::clamp(ty[j].first, 0, field.height - 1));
    r_hi = std::max(r_hi, std::clamp(ty[j].first + static_cast<int>(ty[j].weight.size()) - 1, 0, field.height - 1) + 1);
  }
  // Pass 1: filter along x (rows r_lo…r_hi, outputs i_lo…i_hi); rows in parallel.
  const int cols = i_hi - i_lo;
  std::vector<double> tmp(static_cast<std::size_t>(r_hi - r_lo) * cols, 0.0);
  auto filter_rows = [&](int ra, int rb) {
    for (int r = ra; r < rb; ++r) {
      const float* src = field.heights.data() + static_cast<std::size_t>(r) * field.width;
      double* dst = tmp.data() + static_cast<std::size_t>(r - r_lo) * cols - i_lo;
      for (int i = i_lo; i < i_hi; ++i) {
        const Taps& t = tx[i];
        const int nt = static_cast<int>(t.weight.size());
        double acc = 0.0;
        if (t.first >= 0 && t.first + nt <= field.width) {  // interior: no clamping
          const float* s0 = src + t.first;
          for (int q = 0; q < nt; ++q) acc += t.weight[q] * s0[q];
        } else {
          for (int q = 0; q < nt; ++q) acc += t.weight[q] * src[std::clamp(t.first + q, 0, field.width - 1)];
        }
        dst[i] = acc;
      }
    }
  };
  in_row_chunks(r_lo, r_hi, static_cast<std::size_t>(cols) * tx[i_lo].weight.size(), filter_rows);
  // Pass 2: filter along y.
  for (int j = j_lo; j < j_hi; ++j) {
    const Taps& t = ty[j];
    for (int i = i_lo; i < i_hi; ++i) {
      double acc = 0.0;
      for (std::size_t q = 0; q < t.weight.size(); ++q) {
        const int r = std::clamp(t.first + static_cast<int>(q), 0, field.height - 1);
        acc += t.weight[q] * tmp[static_cast<std::size_t>(r - r_lo) * cols + (i - i_lo)];
      }
      lv.samples[static_cast<std::size_t>(j) * lv.width + i] = static_cast<float>(acc);
    }
  }
  // The interpolating coefficients depend on the whole level (an IIR filter).
  compute_coeffs(lv);
}

float HeightPyramid::sample(int l, double x0, double y0, Interpolation interp) const {
  const PyramidLevel& lv = levels_.at(l);
  const double x = lv.to_level_x(x0), y = lv.to_level_y(y0);
  return interp == Interpolation::Bilinear ? sample_bilinear(lv, x, y) : sample_bspline(lv, x, y);
}

bool HeightPyramid::is_stale(const HeightField& field) const {
  return !built_ || field.width != width_ || field.height != height_ || field.revision != revision_;
}

bool HeightPyramid::update(const HeightField& field) {
  if (!is_stale(field)) return false;
  if (!built_ || field.width != width_ || field.height != height_ || field.revision != revision_ + 1) {
    build(field, options_);
    return true;
  }
  for (int l = 0; l < levels(); ++l) compute_level(field, l, field.last_dirty);
  revision_ = field.revision;
  return true;
}

}  // namespace skylit::terrain
