// The horizon sweep (horizon_sweep.h) against derivations that share neither its hull
// nor its curvature transform: a brute-force far field per texel (the texel's own ray
// moved onto its owner line, the curvature formula as written), the exact march where
// the sweep lines pass through every texel (cardinal and 45° headings), its error
// elsewhere, edge cases, and the reference pipeline's use of it.
#include "horizon_scenes.h"

#include "shading/horizon/horizon_exact.h"
#include "shading/horizon/horizon_ray.h"
#include "shading/horizon/horizon_subsample.h"
#include "shading/horizon/horizon_sweep.h"
#include "shading/products.h"
#include "shading/reference_pipeline.h"
#include "terrain/dem_reader.h"
#include "terrain/synthetic.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace skylit::horizon {
namespace {

using shading::compute_product;  // the reference pipeline's use of the sweep
using shading::Product;
using shading::ProductBands;
using shading::ProductOptions;
using shading::svf_from_horizon;
using shading::uses_sweep;
using terrain::HeightField;
constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kInf = std::numeric_limits<double>::infinity();

// White noise in [0, 1) (splitmix64), the same on every standard library.
double noise(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return static_cast<double>((x ^ (x >> 31)) >> 11) * 0x1.0p-53;
}

// w × h texels of dx × dy metres: white noise of `relief` metres, the roughest field
// there is (neighbouring lines see unrelated heights), in a bowl `bowl` metres deep at
// the corners (far samples rise, so that far maxima and curvature matter).
HeightField rough_field(int w, int h, double dx, double dy, double relief, std::uint64_t seed, double bowl = 0.0) {
  HeightField f(w, h, dx);
  f.dy = dy;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const double x = 2.0 * i / std::max(w - 1, 1) - 1.0, y = 2.0 * j / std::max(h - 1, 1) - 1.0;
      f.at(i, j) = static_cast<float>(relief * noise(seed * 1000003u + j * w + i) + bowl * (x * x + y * y) / 2);
    }
  return f;
}

// Rows spaced like a geographic grid's: dx ∝ cos φ from φ0 to φ1 over the rows.
void make_geographic(HeightField& f, double dx0, double lat0_deg, double lat1_deg) {
  for (int j = 0; j < f.height; ++j) {
    const double lat = (lat0_deg + (lat1_deg - lat0_deg) * j / std::max(f.height - 1, 1)) * kDeg;
    f.dx_per_row[j] = dx0 * std::cos(lat) / std::cos(lat0_deg * kDeg);
  }
}

MarchOptions sweep_options(int near_steps, int lines, double radius_m = 6371000.0) {
  MarchOptions o;
  o.method = HorizonMethod::Sweep;
  o.sweep_near_steps = near_steps;
  o.sweep_lines = lines;
  o.curvature.radius_m = radius_m;
  return o;
}

Heading heading_deg(double geographic_deg) { return heading_from_geographic(geographic_deg * kDeg); }

// "<scene> A<deg> K<k> L<lines>" for failure messages.
std::string case_name(const char* scene, double deg, int near_steps, int lines) {
  char text[96];
  std::snprintf(text, sizeof text, "%s A%g K%d L%d", scene, deg, near_steps, lines);
  return text;
}

// Horizons (rad) of every texel, [j·width + i].
std::vector<double> sweep_horizons(const HeightField& f, Heading u, const MarchOptions& o) {
  const std::vector<std::uint16_t> far = sweep_far_slopes(f, u, o);
  std::vector<double> out(f.size());
  for (int j = 0; j < f.height; ++j)
    for (int i = 0; i < f.width; ++i)
      out[j * f.width + i] = sweep_max_elevation(f, i, j, u, far[j * f.width + i], o);
  return out;
}
std::vector<double> exact_horizons(const HeightField& f, Heading u, const MarchOptions& o) {
  const ExactMarch m{0.5, o.max_distance_m, o.curvature};
  std::vector<double> out(f.size());
  for (int j = 0; j < f.height; ++j)
    for (int i = 0; i < f.width; ++i) out[j * f.width + i] = exact_max_elevation(f, i, j, u, m);
  return out;
}

// Both −∞ (no step on the grid), or within tol (rad).
void expect_equal_horizons(const std::vector<double>& sweep, const std::vector<double>& exact, double tol,
                           const std::string& what) {
  for (std::size_t t = 0; t < sweep.size(); ++t) {
    if (std::isinf(exact[t]) || std::isinf(sweep[t])) {
      EXPECT_EQ(sweep[t], exact[t]) << what << " texel " << t;
      continue;
    }
    EXPECT_NEAR(sweep[t], exact[t], tol) << what << " texel " << t;
  }
}

// The far-slope code's variable x = s/(1 + |s|) (horizon_sweep.h).
double code_x(double s) { return s / (1.0 + std::abs(s)); }
// A far slope's code lowers it by less than a step of x, 1/h, and dθ/dx ≤ 2: 2/h rad of
// horizon angle; plus float rounding.
const double kCodeTolRad = 2.0 / kFarCodeHalfRange + 1e-6;

struct FarSlope {
  double slope = -kInf;  // −∞: no far sample on the grid
  int step = 0;          // the step k of the maximum
};

// The far slope of texel (i, j) as the header defines it, computed directly: steps
// k ≥ K + 1 of the texel's own ray (ray_point), moved across the heading by the offset
// of its owner line (at most half the line spacing), where on the grid; slope
// (z − t²/(2R_eff) − h₀)/t, R_eff = R/(1 − k_refr).
FarSlope brute_far_slope(const HeightField& f, int i, int j, Heading u, const MarchOptions& o) {
  const SweepGeometry g = sweep_geometry(f, u, o.sweep_lines);
  const double a = g.x_dominant ? i : j, b = g.x_dominant ? j : i;
  const double c_texel = b - g.r * a, c_line = g.c_low + g.owner(a, b) * g.spacing();
  EXPECT_LE(std::abs(c_line - c_texel), 0.5 / o.sweep_lines + 1e-9) << "lateral offset at " << i << "," << j;
  const double r_eff = o.curvature.radius_m / (1.0 - o.curvature.refraction_k);
  const double h0 = f.at(i, j), step = exact_step_length(f, j, u, 0.5);
  FarSlope best;
  for (int k = o.sweep_near_steps + 1; k <= 2 * std::max(f.width, f.height); ++k) {
    const double t = k * step;
    if (o.max_distance_m > 0.0 && t > o.max_distance_m * (1.0 + 1e-12)) break;  // as the exact march stops
    GridPoint p = ray_point(f, i, j, u, t);
    (g.x_dominant ? p.y : p.x) += c_line - c_texel;
    if (!on_grid(f, p)) continue;
    const double drop = o.curvature.enabled ? t * t / (2.0 * r_eff) : 0.0;
    const double slope = (bilinear_height(f, p) - drop - h0) / t;
    if (slope > best.slope) best = {slope, k};
  }
  return best;
}

// Every texel's far slope equals the brute force; returns how many maxima lie beyond
// the first far step (the hull walk had to leave its nearest vertex).
int expect_far_slopes_match(const HeightField& f, Heading u, const MarchOptions& o, const std::string& what) {
  const std::vector<std::uint16_t> far = sweep_far_slopes(f, u, o);
  int beyond_first = 0;
  for (int j = 0; j < f.height; ++j)
    for (int i = 0; i < f.width; ++i) {
      const FarSlope b = brute_far_slope(f, i, j, u, o);
      const std::uint16_t code = far[j * f.width + i];
      if (std::isinf(b.slope)) {
        EXPECT_EQ(code, kFarCodeNone) << what << " at " << i << "," << j;
        continue;
      }
      // Rounded down by less than a step of x = s/(1 + |s|), up to float's rounding.
      const double below = code_x(b.slope) - code_x(decode_far_slope(code));
      EXPECT_GE(below, -1e-6) << what << " at " << i << "," << j;
      EXPECT_LT(below, 1.0 / kFarCodeHalfRange + 1e-6) << what << " at " << i << "," << j;
      beyond_first += b.step > o.sweep_near_steps + 1;
    }
  return beyond_first;
}

// Geographic azimuths (deg): cardinal, both dominant axes in all four quadrants for
// dx = 30, dy = 20 (x dominates from atan(30/20) = 56.31° to 123.69°, …), and the tie.
const std::vector<double> kHeadings = {0, 20, 56.309932474020215, 70, 90, 110, 160, 180, 200, 250, 270, 290, 340};

TEST(HorizonSweep, FarSlopeCodesRoundDownWithinTheirAngleBound) {
  EXPECT_EQ(encode_far_slope(-kInf), kFarCodeNone);
  EXPECT_EQ(decode_far_slope(kFarCodeNone), -kInf);
  EXPECT_EQ(encode_far_slope(kInf), kFarCodeMax);  // a vertical wall: the largest finite code
  EXPECT_EQ(encode_far_slope(1e30), kFarCodeMax);
  EXPECT_EQ(encode_far_slope(-1e30), 1);  // finite slopes never read as "none"
  EXPECT_TRUE(std::isfinite(decode_far_slope(kFarCodeMax)));
  // Open ground stays open: 0 is a code, and a slope just below it decodes below it.
  EXPECT_EQ(decode_far_slope(encode_far_slope(0.0)), 0.0f);
  EXPECT_LT(decode_far_slope(encode_far_slope(-1e-9)), 0.0f);
  // Decoded slopes rise with the code, and a slope between two codes' takes the lower.
  for (int q = 1; q < kFarCodeMax; ++q) {
    const double lo = decode_far_slope(static_cast<std::uint16_t>(q));
    const double hi = decode_far_slope(static_cast<std::uint16_t>(q + 1));
    ASSERT_GT(hi, lo) << q;
    ASSERT_EQ(encode_far_slope(0.5 * (lo + hi)), q) << q;
  }
  // The decoded angle is never above the true one and below it by less than 2/h rad,
  // over slopes from cliffs down (log-spaced, both signs).
  double worst = 0.0;
  for (int e = -60; e <= 60; ++e)
    for (double sign : {-1.0, 1.0}) {
      const double s = sign * std::pow(10.0, e / 15.0) * 1.2345;
      const double below = std::atan(s) - std::atan(decode_far_slope(encode_far_slope(s)));
      EXPECT_GE(below, -1e-7) << s;  // float's rounding of the decoded slope
      worst = std::max(worst, below);
    }
  EXPECT_LT(worst, 2.0 / kFarCodeHalfRange);
  EXPECT_GT(worst, 0.5 / kFarCodeHalfRange);  // the bound is not loose by a decade
}

TEST(HorizonSweep, FarSlopesEqualABruteForceOnTheOwnerLine) {
  // Earth radius 3 km: 145 m of drop at 1 km, against 30 m of noise in a 200 m bowl.
  const HeightField f = rough_field(37, 29, 30.0, 20.0, 30.0, 1, 200.0);
  for (auto [k, lines] : {std::pair{0, 1}, {4, 2}, {3, 3}}) {
    MarchOptions o = sweep_options(k, lines, 3e3), flat = o;
    flat.curvature.enabled = false;
    int beyond_first = 0, curved = 0, finite = 0;
    for (double deg : kHeadings) {
      const std::string what = case_name("rough", deg, k, lines);
      beyond_first += expect_far_slopes_match(f, heading_deg(deg), o, what);
      for (int j = 0; j < f.height; ++j)
        for (int i = 0; i < f.width; ++i) {
          const FarSlope b = brute_far_slope(f, i, j, heading_deg(deg), o);
          if (std::isinf(b.slope)) continue;
          ++finite;
          curved += brute_far_slope(f, i, j, heading_deg(deg), flat).step != b.step;
        }
    }
    // Not vacuous: the hull's maximum is often not its nearest sample, and curvature
    // often moves the maximum to another sample.
    EXPECT_GT(beyond_first, finite / 4) << k << " " << lines;
    EXPECT_GT(curved, finite / 20) << k << " " << lines;
  }
}

TEST(HorizonSweep, BoundedFarSlopesEqualABruteForceWithinTheDistance) {
  // The field spans 1080 × 560 m: distances from a few far steps to most of its width,
  // and one between two samples' distances (a step is 15 m along rows, 10 along columns).
  const HeightField f = rough_field(37, 29, 30.0, 20.0, 30.0, 11, 200.0);
  for (double d : {95.0, 137.5, 333.0, 700.0})
    for (auto [k, lines] : {std::pair{0, 1}, {4, 2}, {3, 3}}) {
      MarchOptions o = sweep_options(k, lines, 3e3), open = o;
      o.max_distance_m = d;
      ASSERT_TRUE(sweep_bounded(f, o));
      ASSERT_TRUE(sweep_applicable(f, o)) << sweep_inapplicable_reason(f, o);
      int cut = 0, finite = 0;
      for (double deg : kHeadings) {
        expect_far_slopes_match(f, heading_deg(deg), o, case_name("bounded", deg, k, lines) + " D" + std::to_string(d));
        for (int j = 0; j < f.height; ++j)
          for (int i = 0; i < f.width; ++i) {
            const FarSlope b = brute_far_slope(f, i, j, heading_deg(deg), o);
            if (std::isinf(b.slope)) continue;
            ++finite;
            cut += brute_far_slope(f, i, j, heading_deg(deg), open).slope != b.slope;
          }
      }
      // Not vacuous: the bound hides the unbounded maximum of many texels.
      EXPECT_GT(cut, finite / 20) << d << " " << k << " " << lines;
    }
}

// The texels of `inner` (a window of `outer` at (x0, y0)) whose search of distance d
// (plus a texel for the owner line's offset) stays inside the window along u.
std::vector<std::pair<int, int>> texels_searching_inside(const HeightField& inner, Heading u, double d) {
  std::vector<std::pair<int, int>> out;
  for (int j = 0; j < inner.height; ++j)
    for (int i = 0; i < inner.width; ++i) {
      const double ei = u.east / inner.dx(j), ej = -u.north / inner.dy;  // texels per metre
      const double norm = std::hypot(ei, ej);
      const double x = i + ei * d + ei / norm, y = j + ej * d + ej / norm;
      if (x >= 0 && y >= 0 && x <= inner.width - 1 && y <= inner.height - 1) out.emplace_back(i, j);
    }
  return out;
}

TEST(HorizonSweep, WindowsOfOneRasterSweepTheSameLines) {
  // A window keeps its place in the raster (origin_column, origin_row), so its lines are
  // the raster's: a texel whose bounded search stays inside the window gets the whole
  // raster's code (±1 for the rounding of positions taken from another origin).
  const HeightField whole = rough_field(70, 60, 30.0, 20.0, 30.0, 12, 200.0);
  HeightField window(41, 37, 30.0);
  window.dy = 20.0;
  window.dx_per_row.assign(window.height, 30.0);
  const int x0 = 17, y0 = 11;
  for (int j = 0; j < window.height; ++j)
    for (int i = 0; i < window.width; ++i) window.at(i, j) = whole.at(x0 + i, y0 + j);
  HeightField unaligned = window;
  window.origin_column = x0, window.origin_row = y0;
  int compared = 0, off_unaligned = 0;
  for (double deg : kHeadings)
    for (int lines : {1, 2, 3}) {
      MarchOptions o = sweep_options(4, lines, 6.371e6);
      o.max_distance_m = 300.0;
      const Heading u = heading_deg(deg);
      const auto outer = sweep_far_slopes(whole, u, o), inner = sweep_far_slopes(window, u, o),
                 other = sweep_far_slopes(unaligned, u, o);
      for (auto [i, j] : texels_searching_inside(window, u, o.max_distance_m)) {
        const int a = outer[(y0 + j) * whole.width + x0 + i], b = inner[j * window.width + i];
        EXPECT_LE(std::abs(a - b), 1) << case_name("window", deg, 4, lines) << " at " << i << "," << j;
        off_unaligned += std::abs(a - int{other[j * window.width + i]}) > 1;
        ++compared;
      }
    }
  ASSERT_GT(compared, 5000);
  // Not vacuous: lines laid from the window's own corner see other samples.
  EXPECT_GT(off_unaligned, compared / 10);
}

TEST(HorizonSweep, AWantedRegionGetsTheWholeFieldsCodesAndTheRestIsSkipped) {
  // Projected and geographic rows, unbounded and bounded: the region's texels get the
  // codes of the sweep without one, bit for bit; most texels away from it are skipped.
  HeightField projected = rough_field(90, 70, 30.0, 20.0, 30.0, 21, 200.0), geographic = projected;
  make_geographic(geographic, 30.0, 50.0, 51.2);
  const terrain::PixelRect region{23, 17, 31, 25};
  for (const HeightField* f : {&projected, &geographic})
    for (double d : {0.0, 400.0})
      for (int lines : {1, 2}) {
        MarchOptions o = sweep_options(4, lines, 6.371e6), wanted = o;
        o.max_distance_m = wanted.max_distance_m = d;
        wanted.region = region;
        std::size_t outside = 0, skipped = 0;
        for (double deg : kHeadings) {
          const Heading u = heading_deg(deg);
          const auto all = sweep_far_slopes(*f, u, o, 0), part = sweep_far_slopes(*f, u, wanted, 0);
          for (int j = 0; j < f->height; ++j)
            for (int i = 0; i < f->width; ++i) {
              const std::size_t t = static_cast<std::size_t>(j) * f->width + i;
              if (i >= region.x0 && i < region.x1() && j >= region.y0 && j < region.y1()) {
                ASSERT_EQ(part[t], all[t]) << case_name("region", deg, 4, lines) << " D" << d << " at " << i << "," << j;
              } else if (all[t] != kFarCodeNone) {
                ++outside;
                skipped += part[t] == kFarCodeNone;
              }
            }
        }
        EXPECT_GT(skipped, outside / 2) << (f == &geographic ? "geographic" : "projected") << " D" << d;
      }
}

TEST(HorizonSweep, AnObserverStepKeepsTheCoarseCodesAndLeavesTheRestNone) {
  // A sub-sampled field's observers (horizon_subsample.h), on projected and geographic
  // rows, unbounded and bounded, with and without a region grown by its coarse texels:
  // the coarse texels (0, s, 2s, … and the last index, restated here) get the codes of
  // the sweep with s = 1, bit for bit, the others none.
  HeightField projected = rough_field(61, 47, 30.0, 20.0, 30.0, 8, 200.0), geographic = projected;
  make_geographic(geographic, 30.0, 50.0, 51.2);
  for (const HeightField* f : {&projected, &geographic})
    for (double d : {0.0, 400.0})
      for (int s : {2, 4})
        for (const terrain::PixelRect region : {terrain::PixelRect{}, terrain::PixelRect{13, 9, 21, 17}}) {
          auto coarse = [&](int t, int n) { return t % s == 0 || t == n - 1; };
          MarchOptions o = sweep_options(4, 1, 6.371e6), part_options = o;
          o.max_distance_m = part_options.max_distance_m = d;
          part_options.region = subsample_region(*f, region, s);
          for (double deg : kHeadings) {
            const Heading u = heading_deg(deg);
            const auto all = sweep_far_slopes(*f, u, o, 0);
            const auto part = sweep_far_slopes(*f, u, part_options, 0, -std::numeric_limits<double>::infinity(), s);
            for (int j = 0; j < f->height; ++j)
              for (int i = 0; i < f->width; ++i) {
                const std::size_t t = static_cast<std::size_t>(j) * f->width + i;
                const bool in_region = region.empty() || (i >= region.x0 && i < region.x1() && j >= region.y0 &&
                                                          j < region.y1());
                if (!coarse(i, f->width) || !coarse(j, f->height)) {
                  ASSERT_EQ(part[t], kFarCodeNone) << case_name("step", deg, 4, 1) << " s" << s << " at " << i << "," << j;
                } else if (in_region) {
                  ASSERT_EQ(part[t], all[t]) << case_name("step", deg, 4, 1) << " s" << s << " at " << i << "," << j;
                }
              }
          }
        }
  EXPECT_THROW(sweep_far_slopes(projected, heading_deg(30), sweep_options(4, 1), 1,
                                -std::numeric_limits<double>::infinity(), 0),
               std::invalid_argument);
}

TEST(HorizonSweep, ASubsampledRegionGrowsToTheCoarseTexelsItsTexelsMix) {
  // Texel t mixes the coarse positions ⌊t/s⌋·s and min(⌈t/s⌉·s, n − 1), restated here.
  const HeightField f = rough_field(23, 18, 30.0, 20.0, 30.0, 2, 200.0);
  for (int s : {2, 4}) {
    auto lo = [&](int t) { return t / s * s; };
    auto hi = [&](int t, int n) { return std::min((t + s - 1) / s * s, n - 1); };
    EXPECT_EQ(subsample_region(f, {5, 3, 6, 7}, s),
              (terrain::PixelRect{lo(5), lo(3), hi(10, f.width) - lo(5) + 1, hi(9, f.height) - lo(3) + 1}));
    EXPECT_EQ(subsample_region(f, {20, 15, 10, 10}, s), (terrain::PixelRect{lo(20), lo(15), 23 - lo(20), 18 - lo(15)}));
    EXPECT_EQ(subsample_region(f, {}, s), terrain::PixelRect{});  // the whole field stays "all"
    EXPECT_EQ(subsample_region(f, {30, 30, 4, 4}, s), (terrain::PixelRect{30, 30, 4, 4}));  // outside: unchanged
  }
  EXPECT_EQ(subsample_region(f, {5, 3, 6, 7}, 1), (terrain::PixelRect{5, 3, 6, 7}));
}

TEST(HorizonSweep, ThreadsSplitTheLinesWithoutChangingACode) {
  // Hundreds of lines, so every thread takes several tasks of 32 lines.
  const HeightField f = rough_field(230, 170, 30.0, 20.0, 30.0, 3, 200.0);
  for (double deg : kHeadings) {
    const MarchOptions o = sweep_options(4, 2, 6.371e6);
    const std::vector<std::uint16_t> one = sweep_far_slopes(f, heading_deg(deg), o, 1);
    ASSERT_GT(std::count_if(one.begin(), one.end(), [](std::uint16_t q) { return q != kFarCodeNone; }), f.size() / 2);
    for (unsigned threads : {3u, 0u}) EXPECT_EQ(sweep_far_slopes(f, heading_deg(deg), o, threads), one) << deg;
    MarchOptions bounded = o;
    bounded.max_distance_m = 1500.0;
    const std::vector<std::uint16_t> window = sweep_far_slopes(f, heading_deg(deg), bounded, 1);
    EXPECT_NE(window, one) << deg;
    EXPECT_EQ(sweep_far_slopes(f, heading_deg(deg), bounded, 0), window) << deg;
  }
}

TEST(HorizonSweep, AFloorKeepsEveryCodeThatMayReachIt) {
  // Against the sweep without a floor: a texel whose far slope reaches the floor keeps its
  // code, any other may drop to a lower one or "none", and most drop to "none" (or the
  // floor saved nothing). Rough
  // noise (the 3 × 3 bound at its loosest), a smooth scene, bounded and not, the sun's
  // knobs (K 8, 3 lines) and the sky's, headings off and on the axes (x- and y-led).
  terrain::SyntheticOptions smooth_options;
  smooth_options.width = smooth_options.height = 128;
  const HeightField noisy = rough_field(150, 110, 30.0, 30.0, 60.0, 7, 300.0), smooth = terrain::make_synthetic_terrain(smooth_options);
  for (const HeightField* f : {&noisy, &smooth})
    for (const int lines : {3, 1})
      for (const double distance : {0.0, 2000.0})  // 0: the DEM's extent
        for (const double floor_deg : {3.0, 20.0, 50.0}) {
          MarchOptions o = sweep_options(lines == 3 ? 8 : 4, lines);
          o.max_distance_m = distance;
          const double floor = std::tan(floor_deg * kDeg);
          std::size_t kept = 0, dropped = 0, texels = 0;
          for (const double deg : {0.0, 20.0, 56.309932474020215, 110.0, 200.0, 290.0}) {
            const std::vector<std::uint16_t> full = sweep_far_slopes(*f, heading_deg(deg), o, 2);
            const std::vector<std::uint16_t> floored = sweep_far_slopes(*f, heading_deg(deg), o, 2, floor);
            texels += full.size();
            for (std::size_t t = 0; t < full.size(); ++t) {
              const std::string what = case_name(f == &noisy ? "noise" : "scene", deg, o.sweep_near_steps, lines) +
                                       " D" + std::to_string(distance) + " floor " + std::to_string(floor_deg) +
                                       " texel " + std::to_string(t);
              if (decode_far_slope(full[t]) >= floor) {
                ASSERT_EQ(floored[t], full[t]) << what;
                ++kept;
              } else if (floored[t] != full[t]) {  // fewer samples seen: a lower slope, or none
                ASSERT_LT(floored[t], full[t]) << what;
                dropped += floored[t] == kFarCodeNone;
              }
            }
          }
          // The floor at 3° lies below most far slopes of the noise's bowl: little to drop.
          // The sun's knobs settle most texels under a floor of 20° or more: measured 70–95 %
          // of them (the scene at 20° the fewest; noise K 4 one line 39 %).
          if (lines == 3 && floor_deg > 10.0) {
            EXPECT_GT(dropped, 0.6 * (texels - kept)) << (f == &noisy ? "noise" : "scene") << " floor " << floor_deg;
          }
        }
}

TEST(HorizonSweep, EqualsTheExactMarchWhereEveryTexelLiesOnALine) {
  // Cardinal headings: lines along rows or columns, on any grid. 45° on square texels:
  // lines through texel centres too (c = b ∓ a is an integer, like the lines' c).
  const HeightField rect = rough_field(37, 29, 30.0, 20.0, 150.0, 2), square = rough_field(23, 17, 25.0, 25.0, 150.0, 3);
  for (double radius : {6371e3, 20e3})
    for (int k : {0, 4})
      for (int lines : {1, 2, 3})
        for (double d : {0.0, 180.0, 400.0}) {  // the DEM extent, and bounded searches
          MarchOptions o = sweep_options(k, lines, radius);
          o.max_distance_m = d;
          for (double deg : {0.0, 90.0, 180.0, 270.0}) {
            const std::string what = case_name("rect", deg, k, lines) + " D" + std::to_string(d);
            expect_equal_horizons(sweep_horizons(rect, heading_deg(deg), o), exact_horizons(rect, heading_deg(deg), o),
                                  kCodeTolRad, what);
          }
          for (double deg : {0.0, 45.0, 90.0, 135.0, 180.0, 225.0, 270.0, 315.0}) {
            const std::string what = case_name("square", deg, k, lines) + " D" + std::to_string(d);
            expect_equal_horizons(sweep_horizons(square, heading_deg(deg), o),
                                  exact_horizons(square, heading_deg(deg), o), kCodeTolRad, what);
          }
        }
}

// RMSE (deg) of the sweep against the exact march over every texel and 16 headings
// off the grid's axes and diagonals, where both are finite; −∞ must agree (K ≥ 1).
class SweepError {
 public:
  explicit SweepError(const HeightField& f, const MarchOptions& truth = MarchOptions{}) : f_(f) {
    for (int k = 0; k < 16; ++k) {
      headings_.push_back(heading_deg((k + 0.3) * 22.5));
      exact_.push_back(exact_horizons(f, headings_.back(), truth));
    }
  }
  double rmse(const MarchOptions& o) const {
    double sum = 0;
    long n = 0;
    for (std::size_t k = 0; k < headings_.size(); ++k) {
      const auto s = sweep_horizons(f_, headings_[k], o);
      for (std::size_t t = 0; t < s.size(); ++t) {
        if (std::isinf(s[t]) || std::isinf(exact_[k][t])) {
          EXPECT_EQ(s[t], exact_[k][t]) << "texel " << t;
          continue;
        }
        sum += std::pow((s[t] - exact_[k][t]) / kDeg, 2), ++n;
      }
    }
    return std::sqrt(sum / n);
  }

 private:
  const HeightField& f_;
  std::vector<Heading> headings_;
  std::vector<std::vector<double>> exact_;
};

// Expects the RMSE at K = 4, lines = 2 below `bound` (deg), and falling with the lines'
// lateral offset (≤ 1/(2·lines) texel): the mean offset halves from 1 to 2 lines and
// shrinks by 1/3 from 2 to 3, the measured ratios are ≈ 0.5 and ≈ 0.7.
void expect_accuracy(const HeightField& f, double bound, const std::string& what) {
  const SweepError error(f);
  const double l1 = error.rmse(sweep_options(4, 1)), l2 = error.rmse(sweep_options(4, 2)),
               l3 = error.rmse(sweep_options(4, 3));
  std::printf("%s: sweep RMSE at K = 4: %.3f° (1 line), %.3f° (2), %.3f° (3)\n", what.c_str(), l1, l2, l3);
  EXPECT_LT(l2, bound) << what;
  EXPECT_LT(l2, 0.6 * l1) << what;
  EXPECT_LT(l3, 0.8 * l2) << what;
}

TEST(HorizonSweep, ErrorAgainstTheExactMarchIsBoundedAndFallsWithMoreLines) {
  // The built-in scene at 96² (30 m, 1800 m of relief in 2.9 km: steeper than most real
  // terrain): measured 1.11°, 0.55°, 0.38° for 1, 2, 3 lines; bound 0.7°.
  terrain::SyntheticOptions s;
  s.width = s.height = 96;
  expect_accuracy(terrain::make_synthetic_terrain(s), 0.7, "synthetic 96²");
  // Real 30 m SRTM (Big Tujunga canyons, 128² window): measured 0.62°, 0.31°, 0.21°; bound 0.4°.
  const std::string dem = std::string(SKYLIT_SHARED_DIR) + "/dem/big_tujunga_srtm30_utm11n.tif";
  if (!std::filesystem::exists(dem)) {
    std::printf("%s missing: real terrain not measured\n", dem.c_str());
    return;
  }
  terrain::DemReadOptions read;
  read.window = terrain::PixelRect{500, 250, 128, 128};
  expect_accuracy(terrain::read_dem(dem, read).field, 0.4, "Big Tujunga 128²");
}

// Geographic grids (rhumb_rows.h): the lines follow the rays' rhumb curves, so the
// sweep keeps its projected accuracy. Rows from 55° to 70° N put 1.7× between the first
// and last spacing (a real 1° tile has 1.03× at 60° N), so a line that ignored the bend
// would be texels off at the far edge.
TEST(HorizonSweep, GeographicRowsKeepTheProjectedAccuracy) {
  terrain::SyntheticOptions s;
  s.width = s.height = 96;
  // 58° … 62° N puts 1.15× between the first and last rows' spacing (a 1° tile has 1.03×
  // at 60° N), 55° … 70° N 1.7×: a line that ignored the bend would be texels off.
  for (auto [lat0, lat1, bound] : {std::tuple{58.0, 62.0, 1.1}, {55.0, 70.0, 1.2}}) {
    HeightField geographic = terrain::make_synthetic_terrain(s);
    make_geographic(geographic, 30.0, lat0, lat1);
    HeightField projected = geographic;  // the same heights on rows of the mean spacing
    projected.dx_per_row.assign(projected.height, geographic.mean_dx());
    // Meridians are lines through every column: the exact march's own rays.
    for (double radius : {6371e3, 20e3})
      for (int lines : {1, 2}) {
        const MarchOptions o = sweep_options(4, lines, radius);
        for (double deg : {0.0, 180.0})
          expect_equal_horizons(sweep_horizons(geographic, heading_deg(deg), o),
                                exact_horizons(geographic, heading_deg(deg), o), kCodeTolRad,
                                case_name("geographic", deg, 4, lines));
      }
    // Elsewhere the error is near the projected grid's, also with strong curvature
    // (R = 20 km: 56 m of drop over the 2.9 km scene), whose positions along half columns
    // follow D(y). Measured: 1.06× at 58° … 62°, 1.11× at 55° … 70°. A likely cause (not
    // isolated): the exact march steps evenly in metres from each texel, which on bent
    // rows drifts off the half columns the sweep samples.
    for (double radius : {6371e3, 20e3}) {
      MarchOptions truth;
      truth.curvature.radius_m = radius;
      const double rmse_projected = SweepError(projected, truth).rmse(sweep_options(4, 2, radius));
      const double rmse_geographic = SweepError(geographic, truth).rmse(sweep_options(4, 2, radius));
      std::printf("%g° … %g° N, R %g km: sweep RMSE %.3f° projected, %.3f° geographic\n", lat0, lat1, radius / 1e3,
                  rmse_projected, rmse_geographic);
      EXPECT_LT(rmse_geographic, bound * rmse_projected) << lat0 << " " << radius;
    }
  }
  // Real SRTM on a geographic grid (Franconia, 3″, 128² window): the bound of the
  // projected real DEM above.
  const std::string dem = std::string(SKYLIT_SHARED_DIR) + "/dem/franconia_hills_srtm3_4326.tif";
  if (!std::filesystem::exists(dem)) {
    std::printf("%s missing: real terrain not measured\n", dem.c_str());
    return;
  }
  terrain::DemReadOptions read;
  read.window = terrain::PixelRect{500, 500, 128, 128};
  const HeightField franconia = terrain::read_dem(dem, read).field;
  ASSERT_FALSE(one_row_spacing(franconia));
  expect_accuracy(franconia, 0.4, "Franconia 128² (geographic)");
}

TEST(HorizonSweep, TinyFieldsMatchTheBruteForceAndTheExactMarch) {
  // 1×7, 7×1, 2×2 and 1×1: lines one sample long, rays leaving at once; K ≥ twice the
  // side makes every sample a near step, i.e. the exact march.
  std::vector<double> headings = kHeadings;
  headings.insert(headings.end(), {33.3, 45, 135, 225, 315});
  for (auto [w, h] : {std::pair{1, 7}, {7, 1}, {2, 2}, {1, 1}}) {
    const HeightField f = rough_field(w, h, 30.0, 20.0, 50.0, 6);
    for (double deg : headings) {
      char scene[32];
      std::snprintf(scene, sizeof scene, "%dx%d", w, h);
      for (int k : {0, 1})
        for (int lines : {1, 2, 3})
          expect_far_slopes_match(f, heading_deg(deg), sweep_options(k, lines, 20e3), case_name(scene, deg, k, lines));
      const MarchOptions all_near = sweep_options(2 * std::max(w, h), 2, 20e3);
      expect_equal_horizons(sweep_horizons(f, heading_deg(deg), all_near), exact_horizons(f, heading_deg(deg), all_near),
                            1e-12, case_name(scene, deg, all_near.sweep_near_steps, 2));
    }
  }
}

TEST(HorizonSweep, FlatGroundSeesItsOwnCurvatureDrop) {
  // Slope −t/(2R_eff) is largest at the first step: −atan(t₁/(2R_eff)), t₁ half a texel
  // of the dominant axis, wherever that step is on the grid (the exact march's −∞ elsewhere).
  HeightField f(20, 15, 30.0);
  f.dy = 20.0;
  std::fill(f.heights.begin(), f.heights.end(), 100.0f);
  for (int k : {1, 4})
    for (int lines : {1, 2}) {
      const MarchOptions o = sweep_options(k, lines, 20e3);
      const double r_eff = 20e3 / (1.0 - o.curvature.refraction_k);
      for (double deg : kHeadings) {
        const Heading u = heading_deg(deg);
        const double t1 = 0.5 / std::max(std::abs(u.east) / 30.0, std::abs(u.north) / 20.0);
        const auto s = sweep_horizons(f, u, o), e = exact_horizons(f, u, o);
        expect_equal_horizons(s, e, 1e-12, case_name("flat", deg, k, lines));
        int finite = 0;
        for (double v : s) {
          if (std::isinf(v)) continue;
          EXPECT_NEAR(v, -std::atan(t1 / (2.0 * r_eff)), 1e-12);
          ++finite;
        }
        EXPECT_GT(finite, 0);
      }
    }
}

TEST(HorizonSweep, PitCentreSeesTheRim) {
  // The pit of horizon_exact_test. Radially symmetric: a line δ ≤ 1/4 texel beside the
  // centre meets the wall at radius √(t² + δ²), a second-order shift; what remains is
  // bilinear interpolation at other points (≤ h''dx²/8 / r ≈ 5e-4 each; measured ≤ 9e-4).
  const int n = 129;
  const double dx = 1.0, r0 = 8, r1 = 40, depth = 20;
  const auto f = test::radial_pit(n, dx, r0, r1, depth);
  const double gamma = test::pit_rim_elevation(r0, r1, depth, 64.0);
  MarchOptions o = sweep_options(4, 2);
  o.curvature.enabled = false;
  for (int k = 0; k < 16; ++k) {
    const Heading u = heading_deg((k + 0.3) * 22.5);
    const std::vector<std::uint16_t> far = sweep_far_slopes(f, u, o);
    const double s = sweep_max_elevation(f, n / 2, n / 2, u, far[(n / 2) * n + n / 2], o);
    EXPECT_NEAR(s, gamma, 1.5e-3) << k;  // as the exact march (horizon_exact_test)
    EXPECT_NEAR(s, exact_max_elevation(f, n / 2, n / 2, u, ExactMarch{0.5, 0.0, o.curvature}), 1.5e-3) << k;
  }
}

TEST(HorizonSweep, CliffIsSeenAtItsTopEdgeAndNotFromAbove) {
  // Heights 0 west of column 20 and H = 50 m from it on (a one-texel bilinear ramp),
  // the same on every row: at headings where x dominates, the line samples the same x
  // as the texel's ray, so from the foot the maximum is the top edge x = 20, at ground
  // distance (20 − i)·dx / |sin A|: atan(H·|sin A| / ((20 − i)·dx)); from the top, away
  // from the edge, the flat top: 0.
  const int w = 40, h = 21;
  const double dx = 10.0, height = 50.0;
  HeightField f(w, h, dx);
  for (int j = 0; j < h; ++j)
    for (int i = 20; i < w; ++i) f.at(i, j) = static_cast<float>(height);
  for (auto [k, lines] : {std::pair{0, 1}, {4, 2}}) {
    MarchOptions o = sweep_options(k, lines);
    o.curvature.enabled = false;
    for (double deg : {60.0, 90.0, 120.0, 240.0, 270.0, 300.0}) {
      const Heading u = heading_deg(deg);
      const auto s = sweep_horizons(f, u, o), e = exact_horizons(f, u, o);
      for (int j = 6; j <= 14; ++j) {
        const bool east = u.east > 0;
        for (int i = east ? 12 : 21; i <= (east ? 19 : 28); ++i) {
          const double expected = east ? std::atan(height * std::abs(u.east) / ((20 - i) * dx)) : 0.0;
          // Far slopes are 16-bit codes: rounded down by less than kCodeTolRad.
          EXPECT_NEAR(s[j * w + i], expected, kCodeTolRad) << "A" << deg << " K" << k << " at " << i << "," << j;
          EXPECT_NEAR(e[j * w + i], expected, 1e-9) << "A" << deg << " at " << i << "," << j;
        }
      }
    }
  }
}

// With K = 0 the converse may fail: an edge texel whose owner line runs outside the
// grid can have no far sample although its own ray has steps on it (−∞ where the exact
// march is finite; measured: a few texels in 10⁵ on the synthetic scene).
TEST(HorizonSweep, RaysLeavingTheGridAtTheFirstStepHaveNoHorizon) {
  const HeightField f = rough_field(37, 29, 30.0, 20.0, 30.0, 7, 200.0);
  for (int k : {0, 4})
    for (double deg : kHeadings) {
      const Heading u = heading_deg(deg);
      const auto s = sweep_horizons(f, u, sweep_options(k, 2)), e = exact_horizons(f, u, MarchOptions{});
      int none = 0;
      for (int j = 0; j < f.height; ++j)
        for (int i = 0; i < f.width; ++i) {
          const GridPoint first = ray_point(f, i, j, u, exact_step_length(f, j, u, 0.5));
          const bool leaves = !on_grid(f, first);
          none += leaves;
          EXPECT_EQ(std::isinf(e[j * f.width + i]), leaves) << i << "," << j;
          const double v = s[j * f.width + i];
          if (leaves || k > 0) {
            EXPECT_EQ(std::isinf(v), leaves) << "K" << k << " A" << deg << " at " << i << "," << j;
          }
          EXPECT_FALSE(v == kInf);
        }
      EXPECT_GT(none, 0) << deg;  // the edges facing u
    }
}

TEST(HorizonSweep, NodataTexelsAreSweptWithTheirFilledHeights) {
  // As the exact march: heights under nodata are the field's filled ones (a tower here),
  // and nodata texels get horizons like any other (the products mask them).
  HeightField f = rough_field(37, 29, 30.0, 20.0, 30.0, 8, 200.0);
  for (int j = 10; j < 14; ++j)
    for (int i = 15; i < 19; ++i) f.valid[j * f.width + i] = 0, f.at(i, j) = 400.0f;
  for (int k : {0, 4}) {
    const MarchOptions o = sweep_options(k, 2, 20e3);
    for (double deg : kHeadings) expect_far_slopes_match(f, heading_deg(deg), o, case_name("nodata", deg, k, 2));
    for (double deg : {0.0, 90.0, 180.0, 270.0})
      expect_equal_horizons(sweep_horizons(f, heading_deg(deg), o), exact_horizons(f, heading_deg(deg), o),
                            kCodeTolRad, case_name("nodata", deg, k, 2));
  }
  // The tower is seen: 5 texels (100 m) west of it, looking east, above 60°.
  EXPECT_GT(sweep_horizons(f, heading_deg(90), sweep_options(0, 2))[12 * f.width + 10], 60 * kDeg);
}

TEST(HorizonSweep, AppliesToRowsOfNearSpacingsAndDistancesCoveringTheDem) {
  const HeightField f = rough_field(37, 29, 30.0, 20.0, 30.0, 9);
  MarchOptions o = sweep_options(4, 2);
  EXPECT_TRUE(sweep_applicable(f, o));
  EXPECT_EQ(sweep_inapplicable_reason(f, o), "");
  HeightField geographic = f;
  make_geographic(geographic, 30.0, 55.0, 70.0);  // spacings 30 … 17.9 m
  EXPECT_TRUE(sweep_applicable(geographic, o));
  make_geographic(geographic, 30.0, 80.0, 86.0);  // 30 … 12.0 m: more than 2×
  EXPECT_FALSE(sweep_applicable(geographic, o));
  EXPECT_NE(sweep_inapplicable_reason(geographic, o).find("near a pole"), std::string::npos);
  EXPECT_THROW(sweep_far_slopes(geographic, heading_deg(30), o), std::invalid_argument);
  // D bounds the search below the diagonal, √(1080² + 560²) m, and must reach past the
  // near steps: 5 half texels of at most ½·√(30² + 20²) = 18.0 m.
  const double diagonal = std::hypot(36 * 30.0, 28 * 20.0);
  for (double d : {diagonal, diagonal + 1.0, 0.0}) {
    o.max_distance_m = d;
    EXPECT_TRUE(sweep_applicable(f, o)) << d;
    EXPECT_FALSE(sweep_bounded(f, o)) << d;
  }
  for (double d : {diagonal - 0.01, 91.0}) {
    o.max_distance_m = d;
    EXPECT_TRUE(sweep_applicable(f, o)) << d;
    EXPECT_TRUE(sweep_bounded(f, o)) << d;
  }
  o.max_distance_m = 89.0;
  EXPECT_FALSE(sweep_applicable(f, o));
  EXPECT_NE(sweep_inapplicable_reason(f, o).find("near steps"), std::string::npos);
  EXPECT_THROW(sweep_far_slopes(f, heading_deg(30), o), std::invalid_argument);

  MarchOptions bad = sweep_options(-1, 2);
  EXPECT_THROW(validate(bad), std::invalid_argument);
  EXPECT_THROW(sweep_far_slopes(f, heading_deg(30), bad), std::invalid_argument);
  bad = sweep_options(0, 0);
  EXPECT_THROW(validate(bad), std::invalid_argument);
  EXPECT_THROW(sweep_far_slopes(f, heading_deg(30), bad), std::invalid_argument);
  EXPECT_NO_THROW(validate(sweep_options(0, 1)));
}

// NaN (nodata) equal to NaN, everything else bit for bit.
bool same_bands(const ProductBands& a, const ProductBands& b) {
  if (a.data.size() != b.data.size()) return false;
  for (std::size_t t = 0; t < a.data.size(); ++t)
    if (!(a.data[t] == b.data[t] || (std::isnan(a.data[t]) && std::isnan(b.data[t])))) return false;
  return true;
}

TEST(HorizonSweep, ReferencePipelineSweepsWhereItAppliesAndMarchesElsewhere) {
  HeightField f = rough_field(21, 17, 30.0, 20.0, 30.0, 10, 200.0);
  f.valid[5 * f.width + 7] = 0;  // nodata: NaN in the products
  const int w = 8;
  ProductOptions o;
  o.march = sweep_options(2, 3);
  o.march.azimuths = w;
  ASSERT_TRUE(uses_sweep(f, o));
  std::vector<Heading> headings;
  std::vector<std::vector<std::uint16_t>> far;
  for (int k = 0; k < w; ++k) {
    headings.push_back(heading_from_geographic(band_azimuth(k, w)));
    far.push_back(sweep_far_slopes(f, headings.back(), o.march));
  }
  const ProductBands svf = compute_product(f, Product::Svf, o), horizon = compute_product(f, Product::Horizon, o);
  const double r_eff = o.march.curvature.effective_radius();
  std::vector<double> sigma(w);
  for (int j = 0; j < f.height; ++j)
    for (int i = 0; i < f.width; ++i) {
      if (!f.is_valid(i, j)) {
        EXPECT_TRUE(std::isnan(svf.at(0, i, j)));
        continue;
      }
      for (int k = 0; k < w; ++k) sigma[k] = sweep_max_elevation(f, i, j, headings[k], far[k][j * f.width + i], o.march);
      EXPECT_EQ(svf.at(0, i, j), static_cast<float>(svf_from_horizon(sigma))) << i << "," << j;
      // The horizon product floors at the ground seen at the first step, half a texel.
      for (int k = 0; k < w; ++k) {
        const double floor = -std::atan(exact_step_length(f, j, headings[k], 0.5) / (2.0 * r_eff));
        EXPECT_EQ(horizon.at(k, i, j), static_cast<float>(std::max(sigma[k], floor) * 180.0 / std::numbers::pi));
      }
    }
  ProductOptions march = o;
  march.march.method = HorizonMethod::March;
  EXPECT_FALSE(same_bands(svf, compute_product(f, Product::Svf, march)));
  // Sub-sampling keeps the sweep (products_subsample_test.cpp).
  o.subsample = march.subsample = 2;
  EXPECT_TRUE(uses_sweep(f, o));
  EXPECT_FALSE(same_bands(compute_product(f, Product::Svf, o), compute_product(f, Product::Svf, march)));
  // The exact march and rows of several spacings march.
  o.subsample = march.subsample = 1;
  o.exact = march.exact = true;
  EXPECT_FALSE(uses_sweep(f, o));
  EXPECT_TRUE(same_bands(compute_product(f, Product::Horizon, o), compute_product(f, Product::Horizon, march)));
  o.exact = march.exact = false;
  make_geographic(f, 30.0, 80.0, 86.0);  // spacings more than 2× apart
  EXPECT_FALSE(uses_sweep(f, o));
  EXPECT_TRUE(same_bands(compute_product(f, Product::Svf, o), compute_product(f, Product::Svf, march)));
}

}  // namespace
}  // namespace skylit::horizon
