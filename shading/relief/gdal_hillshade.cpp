#include "shading/relief/gdal_hillshade.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>

#if defined(__x86_64__) || defined(_M_X64)
#include <emmintrin.h>
#define SKYLIT_RELIEF_SSE2 1
#endif

namespace skylit::relief {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// a / sqrt(b) as gdaldem computes it on x86-64: the SSE reciprocal square root estimate
// and one Newton step (the exact quotient elsewhere, as gdaldem without SSE2).
double approx_div_sqrt(double a, double b) {
#ifdef SKYLIT_RELIEF_SSE2
  __m128d rb = _mm_load_sd(&b);
  const __m128d half_b = _mm_mul_sd(rb, _mm_set1_pd(0.5));
  rb = _mm_cvtss_sd(rb, _mm_rsqrt_ss(_mm_cvtsd_ss(_mm_setzero_ps(), rb)));
  rb = _mm_mul_sd(rb, _mm_sub_sd(_mm_set1_pd(1.5), _mm_mul_sd(half_b, _mm_mul_sd(rb, rb))));
  double r;
  _mm_store_sd(&r, rb);
  return a * r;
#else
  return a / std::sqrt(b);
#endif
}

// Constants of one run, as gdaldem derives them from its options.
struct Params {
  double inv_ew, inv_ns;  // 1/(ewres·xscale), 1/(nsres·yscale) with nsres < 0 (north up)
  double sin_alt, az, zf, cos_az_cos_alt_z, sin_az_cos_alt_z, square_z;
  double sin_alt_254, cos_az_cos_alt_z_254, sin_az_cos_alt_z_254;
  bool same_res;
  double square_z_inv_res2, cos_term_inv_res, sin_term_inv_res;  // same resolution only
  double sin_alt_127, cos_alt_z_127, cos225_cos_alt_z_127;       // multidirectional
};

Params make_params(double ew, double ns, const HillshadeOptions& o) {
  Params p{};
  p.inv_ns = 1.0 / ns;
  p.inv_ew = 1.0 / ew;
  p.sin_alt = std::sin(o.altitude_deg * kDeg);
  p.az = o.azimuth_deg * kDeg;
  p.zf = o.z / (o.gradient == Gradient::ZevenbergenThorne ? 2 : 8);
  const double cos_alt_z = std::cos(o.altitude_deg * kDeg) * p.zf;
  p.cos_az_cos_alt_z = std::cos(p.az) * cos_alt_z;
  p.sin_az_cos_alt_z = std::sin(p.az) * cos_alt_z;
  p.square_z = p.zf * p.zf;
  p.sin_alt_254 = 254.0 * p.sin_alt;
  p.cos_az_cos_alt_z_254 = 254.0 * p.cos_az_cos_alt_z;
  p.sin_az_cos_alt_z_254 = 254.0 * p.sin_az_cos_alt_z;
  p.same_res = ew == -ns;
  if (p.same_res) {
    p.square_z_inv_res2 = p.square_z * p.inv_ew * p.inv_ew;
    p.cos_term_inv_res = p.cos_az_cos_alt_z_254 * -p.inv_ew;
    p.sin_term_inv_res = p.sin_az_cos_alt_z_254 * p.inv_ew;
  }
  p.sin_alt_127 = 127.0 * p.sin_alt;
  p.cos_alt_z_127 = 127.0 * cos_alt_z;
  p.cos225_cos_alt_z_127 = 127.0 * std::cos(225 * kDeg) * cos_alt_z;
  return p;
}

// The gradient in T's own arithmetic (float or int), then scaled in double.
template <class T>
void gradient(const T* w, Gradient g, const Params& p, double& x, double& y) {
  if (g == Gradient::Horn) {
    x = ((w[0] + w[3] + w[3] + w[6]) - (w[2] + w[5] + w[5] + w[8])) * p.inv_ew;
    y = ((w[6] + w[7] + w[7] + w[8]) - (w[0] + w[1] + w[1] + w[2])) * p.inv_ns;
  } else {
    x = (w[3] - w[5]) * p.inv_ew;
    y = (w[7] - w[1]) * p.inv_ns;
  }
}

template <class T>
float regular(const T* w, Gradient g, const Params& p) {
  double x, y;
  gradient(w, g, p, x, y);
  const double xx_yy = x * x + y * y;
  const double c254 = approx_div_sqrt(p.sin_alt_254 - (y * p.cos_az_cos_alt_z_254 - x * p.sin_az_cos_alt_z_254),
                                      1 + p.square_z * xx_yy);
  return static_cast<float>(c254 <= 0.0 ? 1.0 : 1.0 + c254);
}

// Horn at equal east–west and north–south spacing: gdaldem's shortcut, other rounding.
template <class T>
float same_res(const T* w, const Params& p) {
  T acc_x = w[0] - w[8];
  const T six_two = w[6] - w[2];
  T acc_y = acc_x;
  const T three_five = w[3] - w[5];
  const T one_seven = w[1] - w[7];
  acc_x += three_five;
  acc_y += one_seven;
  acc_x += three_five;
  acc_y += one_seven;
  acc_x += six_two;
  acc_y -= six_two;
  const double x = acc_x, y = acc_y;
  const double xx_yy = x * x + y * y;
  const double c254 =
      approx_div_sqrt(p.sin_alt_254 + (x * p.sin_term_inv_res + y * p.cos_term_inv_res), 1 + p.square_z_inv_res2 * xx_yy);
  return static_cast<float>(c254 <= 0.0 ? 1.0 : 1.0 + c254);
}

// gdaldem's 4-wide SSE loop over integer rows without nodata: the same quotient summed
// in another order and finished in float.
float same_res_vector(const std::int32_t* w, const Params& p) {
  std::int32_t acc_x = w[0] - w[8];
  const std::int32_t six_two = w[6] - w[2];
  std::int32_t acc_y = acc_x;
  const std::int32_t three_five = w[3] - w[5];
  const std::int32_t one_seven = w[1] - w[7];
  acc_x += 2 * three_five + six_two;
  acc_y += 2 * one_seven - six_two;
  const double x = acc_x, y = acc_y;
  const double xx_yy = x * x + y * y;
  const double num = p.sin_alt_254 + p.sin_term_inv_res * x + p.cos_term_inv_res * y;
  const double den = 1.0 + p.square_z_inv_res2 * xx_yy;
  const float res = static_cast<float>(approx_div_sqrt(num, den));
  return std::max(1.0f, res + 1.0f);
}

constexpr double kInvSquareHalfPi = 1.0 / ((std::numbers::pi * std::numbers::pi) / 4);

template <class T>
float combined(const T* w, Gradient g, const Params& p) {
  double x, y;
  gradient(w, g, p, x, y);
  const double slope = (x * x + y * y) * p.square_z;
  double cang = std::acos(
      approx_div_sqrt(p.sin_alt - (y * p.cos_az_cos_alt_z - x * p.sin_az_cos_alt_z), 1 + slope));
  cang = 1 - cang * std::atan(std::sqrt(slope)) * kInvSquareHalfPi;
  return cang <= 0.0 ? 1.0f : static_cast<float>(1.0 + (254.0 * cang));
}

template <class T>
float multidirectional(const T* w, Gradient g, const Params& p) {
  double x, y;
  gradient(w, g, p, x, y);
  const double xx = x * x, yy = y * y, xx_yy = xx + yy;
  if (xx_yy == 0.0) return static_cast<float>(1.0 + p.sin_alt_254);
  const auto pos = [](double v) { return v <= 0.0 ? 0.0 : v; };
  const double v225 = pos(p.sin_alt_127 + (x - y) * p.cos225_cos_alt_z_127);
  const double v270 = pos(p.sin_alt_127 - x * p.cos_alt_z_127);
  const double v315 = pos(p.sin_alt_127 + (x + y) * p.cos225_cos_alt_z_127);
  const double v360 = pos(p.sin_alt_127 - y * p.cos_alt_z_127);
  const double w225 = 0.5 * xx_yy - x * y, w270 = xx, w315 = xx_yy - w225, w360 = yy;
  const double c127 = approx_div_sqrt((w225 * v225 + w270 * v270 + w315 * v315 + w360 * v360) / xx_yy,
                                      1 + p.square_z * xx_yy);
  return static_cast<float>(1.0 + c127);
}

double normalise_angle(double a, double n) {
  a = std::fmod(a, n);
  return a < 0 ? n + a : a;
}

template <class T>
float igor(const T* w, Gradient g, const Params& p) {
  double sx, sy, ax, ay;
  if (g == Gradient::Horn) {
    sx = ((w[0] + w[3] + w[3] + w[6]) - (w[2] + w[5] + w[5] + w[8])) * p.inv_ew;
    sy = ((w[6] + w[7] + w[7] + w[8]) - (w[0] + w[1] + w[1] + w[2])) * p.inv_ns;
    ax = ((w[2] + w[5] + w[5] + w[8]) - (w[0] + w[3] + w[3] + w[6]));
    ay = ((w[6] + w[7] + w[7] + w[8]) - (w[0] + w[1] + w[1] + w[2]));
  } else {
    sx = (w[3] - w[5]) * p.inv_ew;
    sy = (w[7] - w[1]) * p.inv_ns;
    ax = w[5] - w[3];
    ay = w[7] - w[1];
  }
  const double slope_deg = std::atan(std::sqrt(sx * sx + sy * sy) * p.zf) * (180.0 / std::numbers::pi);
  const double aspect = std::atan2(ay, -ax);
  const double two_pi = std::numbers::pi * 2;
  double diff = std::abs(normalise_angle(aspect, two_pi) - normalise_angle(std::numbers::pi * 3 / 2 - p.az, two_pi));
  if (diff > two_pi / 2) diff = two_pi - diff;
  const double shadowness = 1.0 - (slope_deg / 90) * (1 - diff / std::numbers::pi);
  return static_cast<float>(255.0 * shadowness);
}

template <class T>
float shade(const T* w, const HillshadeOptions& o, const Params& p) {
  switch (o.variant) {
    case HillshadeVariant::MultiDirectional: return multidirectional(w, o.gradient, p);
    case HillshadeVariant::Combined: return combined(w, o.gradient, p);
    case HillshadeVariant::Igor: return igor(w, o.gradient, p);
    case HillshadeVariant::Regular: break;
  }
  return o.gradient == Gradient::Horn && p.same_res ? same_res(w, p) : regular(w, o.gradient, p);
}

// A height or nodata, in T.
template <class T>
using Cell = std::optional<T>;

// gdaldem's extrapolation past an edge: 2a − b, nodata if either is.
template <class T>
Cell<T> extrapolate(Cell<T> a, Cell<T> b) {
  if (!a || !b) return std::nullopt;
  if constexpr (std::is_integral_v<T>)
    return static_cast<T>(std::clamp<std::int64_t>(2 * static_cast<std::int64_t>(*a) - *b, INT_MIN, INT_MAX));
  else
    return 2 * *a - *b;
}

template <class T>
std::vector<float> run(const terrain::HeightField& f, const HillshadeOptions& o) {
  const int W = f.width, H = f.height;
  const double ew = f.dx(H / 2), ns = -f.dy;
  const Params p = make_params(ew, ns, o);
  const float nodata = std::numeric_limits<float>::quiet_NaN();
  std::vector<float> out(static_cast<std::size_t>(W) * H, nodata);
  const auto cell = [&](int i, int j) -> Cell<T> {
    if (!f.is_valid(i, j)) return std::nullopt;
    return static_cast<T>(f.at(i, j));
  };
  // gdaldem's ComputeVal: nodata centre → nodata; a nodata neighbour → the centre's
  // value with compute_edges, else nodata.
  const auto value = [&](Cell<T> (&win)[9]) -> float {
    if (!win[4]) return nodata;
    T w[9];
    for (int k = 0; k < 9; ++k) {
      if (!win[k] && !o.compute_edges) return nodata;
      w[k] = win[k] ? *win[k] : *win[4];
    }
    return shade(w, o, p);
  };
  std::vector<char> row_has_nodata(H);
  for (int j = 0; j < H; ++j)
    for (int i = 0; i < W && !row_has_nodata[j]; ++i) row_has_nodata[j] = !f.is_valid(i, j);
  const bool vector_path = std::is_integral_v<T> && o.variant == HillshadeVariant::Regular &&
                           o.gradient == Gradient::Horn && p.same_res;
  const auto put = [&](int i, int j, float v) { out[static_cast<std::size_t>(j) * W + i] = v; };
  if (W < 2 || H < 2) return out;
  for (int j = 1; j < H - 1; ++j) {
    if (o.compute_edges) {
      Cell<T> win[9] = {extrapolate(cell(0, j - 1), cell(1, j - 1)), cell(0, j - 1), cell(1, j - 1),
                        extrapolate(cell(0, j), cell(1, j)),         cell(0, j),     cell(1, j),
                        extrapolate(cell(0, j + 1), cell(1, j + 1)), cell(0, j + 1), cell(1, j + 1)};
      put(0, j, value(win));
      const int e = W - 1;
      Cell<T> win2[9] = {cell(e - 1, j - 1), cell(e, j - 1), extrapolate(cell(e, j - 1), cell(e - 1, j - 1)),
                         cell(e - 1, j),     cell(e, j),     extrapolate(cell(e, j), cell(e - 1, j)),
                         cell(e - 1, j + 1), cell(e, j + 1), extrapolate(cell(e, j + 1), cell(e - 1, j + 1))};
      put(e, j, value(win2));
    }
    int i = 1;
    if (vector_path && !row_has_nodata[j - 1] && !row_has_nodata[j] && !row_has_nodata[j + 1]) {
      // gdaldem's vector loop: blocks of 4 columns starting at 1, 5, 9, … below W − 4;
      // the columns after the last block run the scalar path.
      const int end = W - 4 > 1 ? 1 + 4 * ((W - 4 - 1 + 3) / 4) : 1;
      for (; i < end; ++i) {
        std::int32_t w[9];
        for (int k = 0; k < 9; ++k) w[k] = static_cast<std::int32_t>(f.at(i - 1 + k % 3, j - 1 + k / 3));
        put(i, j, same_res_vector(w, p));
      }
    }
    for (; i < W - 1; ++i) {
      Cell<T> win[9];
      for (int k = 0; k < 9; ++k) win[k] = cell(i - 1 + k % 3, j - 1 + k / 3);
      put(i, j, value(win));
    }
  }
  if (o.compute_edges) {
    for (int r : {0, H - 1}) {
      const int near = r == 0 ? 1 : H - 2;
      for (int i = 0; i < W; ++i) {
        const int c[3] = {i == 0 ? i : i - 1, i, i == W - 1 ? i : i + 1};
        Cell<T> win[9];
        for (int k = 0; k < 3; ++k) {
          const Cell<T> outside = extrapolate(cell(c[k], r), cell(c[k], near));
          win[(r == 0 ? 0 : 6) + k] = outside;
          win[3 + k] = cell(c[k], r);
          win[(r == 0 ? 6 : 0) + k] = cell(c[k], near);
        }
        put(i, r, value(win));
      }
    }
  }
  return out;
}

bool integer_heights(const terrain::HeightField& f) {
  for (std::size_t k = 0; k < f.size(); ++k)
    if (f.valid[k] && (f.heights[k] != std::nearbyint(f.heights[k]) || std::abs(f.heights[k]) > 65535.0f))
      return false;
  return true;
}

}  // namespace

std::vector<float> gdal_hillshade(const terrain::HeightField& field, const HillshadeOptions& options) {
  return integer_heights(field) ? run<std::int32_t>(field, options) : run<float>(field, options);
}

}  // namespace skylit::relief
