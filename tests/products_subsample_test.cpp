// Horizon sub-sampling in the CPU reference (ProductOptions::subsample, products.h):
// raw horizons of the coarse texels (0, s, 2s, … and the last index per axis), marched
// or swept, bilinear elsewhere, a texel's own where a needed coarse sample is nodata or
// −∞. Checked, for the march and the sweep, against independent derivations: the coarse
// grid restated here (not horizon::SubsampleAxis), bilinear mixes of the s = 1 `horizon`
// product computed in the test, −∞ samples found from the first step directly
// (HorizonMarcher; the sweep's half-texel step), and flat ground.
//
// Measured (printed below) on the 80×72 synthetic scene (30 m texels, 1200 m relief in
// 2 km features: horizons change a lot from texel to texel, since the first steps lie
// within a texel or two), W = 16, vs s = 1 of the same method, RMSE (max):
//   march s = 2: svf 0.043 (0.34), skyview 0.014 (0.17), shaded 2.0 codes (23)
//   march s = 4: svf 0.059 (0.34), skyview 0.028 (0.27), shaded 3.8 codes (37)
//   sweep s = 2: svf 0.044 (0.50), skyview 0.015 (0.26), shaded 2.2 codes (33)
//   sweep s = 4: svf 0.066 (0.56), skyview 0.035 (0.53), shaded 4.9 codes (102)
// (the sweep's maxima within s texels of the field's edge, where it mixes the samples
// still on the grid). SubsampledProductsStayCloseToFullResolution bounds them at ≈ 1.3×
// those.
#include "horizon_scenes.h"

#include "shading/horizon/azimuth.h"
#include "shading/horizon/horizon_exact.h"
#include "shading/horizon/horizon_march.h"
#include "shading/horizon/horizon_sweep.h"
#include "shading/products.h"
#include "shading/reference_pipeline.h"
#include "terrain/analytic_scenes.h"
#include "terrain/synthetic.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace skylit::shading {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

// Texel t of an axis of n texels: the coarse positions it mixes, with weights summing
// to 1 (a coarse position itself: one, weight 1). Restated from the definition.
struct Mix {
  std::vector<int> at;
  std::vector<double> weight;
};
Mix mix_of(int t, int n, int s) {
  std::vector<int> coarse;
  for (int p = 0; p < n; p += s) coarse.push_back(p);
  if (coarse.back() != n - 1) coarse.push_back(n - 1);
  if (std::find(coarse.begin(), coarse.end(), t) != coarse.end()) return {{t}, {1.0}};
  const int hi = *std::upper_bound(coarse.begin(), coarse.end(), t);
  const int lo = *(std::upper_bound(coarse.begin(), coarse.end(), t) - 1);
  const double a = static_cast<double>(t - lo) / (hi - lo);
  return {{lo, hi}, {1.0 - a, a}};
}

terrain::HeightField synthetic(int w, int h) {
  terrain::SyntheticOptions o;
  o.width = w;
  o.height = h;
  o.spacing = 30.0;
  o.seed = 3;
  o.feature_size = 2000.0;
  o.relief = 1200.0;
  return terrain::make_synthetic_terrain(o);
}

using horizon::HorizonMethod;
constexpr HorizonMethod kMethods[] = {HorizonMethod::March, HorizonMethod::Sweep};
const char* name(HorizonMethod m) { return m == HorizonMethod::March ? "march" : "sweep"; }

ProductOptions options(int s, HorizonMethod method, int azimuths = 16) {
  ProductOptions o;
  o.march.method = method;
  o.march.azimuths = azimuths;
  o.subsample = s;
  return o;
}

// What each band's first step decides: the `horizon` product's floor (degrees), the
// receiver's ground at the first march distance, −atan(t₁/(2R_eff)), or for the sweep at
// its first half-texel step (products.h; one row spacing here, so any row's); and
// whether a texel has no horizon, its first step leaving the grid.
class FirstStep {
 public:
  FirstStep(const terrain::HeightField& f, const ProductOptions& o) : f_(f), o_(o), marcher_(f, o.march) {}
  double floor_deg(int k) const {
    const double t1 = o_.march.method == HorizonMethod::March ? marcher_.distance(0)
                                                              : horizon::exact_step_length(f_, 0, heading(k), 0.5);
    return -std::atan(t1 / (2.0 * o_.march.curvature.effective_radius())) * kDeg;
  }
  bool unmarched(int i, int j, int k) const {
    const double none = -std::numeric_limits<double>::infinity();
    if (o_.march.method == HorizonMethod::March) return marcher_.max_elevation(i, j, heading(k)) == none;
    return horizon::sweep_max_elevation(f_, i, j, heading(k), horizon::kFarCodeNone, o_.march) == none;
  }

 private:
  horizon::Heading heading(int k) const {
    return horizon::heading_from_geographic(horizon::band_azimuth(k, o_.march.azimuths));
  }
  const terrain::HeightField& f_;
  ProductOptions o_;
  horizon::HorizonMarcher marcher_;
};

TEST(Subsample, Validation) {
  const auto f = terrain::flat_plane(8, 8, 10.0);
  ProductOptions o;
  o.subsample = 2;
  EXPECT_TRUE(uses_sweep(f, o));  // the default sweep sub-samples
  o.march.method = HorizonMethod::March;
  EXPECT_FALSE(uses_sweep(f, o));
  o.subsample = 3;
  EXPECT_THROW(compute_product(f, Product::Svf, o), std::invalid_argument);
  o.subsample = 2;
  o.exact = true;
  try {
    compute_product(f, Product::Svf, o);
    ADD_FAILURE() << "exact with subsample 2 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "subsample does not apply to the exact march (the ground truth)");
  }
}

// Open flat ground with Earth curvature: σ_k = −atan(t₀/(2R_eff)) at every texel whose
// first step lies on the grid (−∞ otherwise, which falls back to the texel's own
// march), so the bilinear mixes are exact and every product equals s = 1.
TEST(Subsample, FlatGroundEqualsFullResolution) {
  const auto f = terrain::flat_plane(45, 41, 25.0);
  for (HorizonMethod m : kMethods) {
    for (int s : {2, 4})
      for (Product p : {Product::Horizon, Product::Svf, Product::Skyview, Product::Shaded}) {
        const ProductBands a = compute_product(f, p, options(1, m)), b = compute_product(f, p, options(s, m));
        double max_diff = 0.0;
        for (std::size_t t = 0; t < a.data.size(); ++t)
          max_diff = std::max(max_diff, std::abs(double(a.data[t]) - b.data[t]));
        EXPECT_LE(max_diff, 1e-9) << product_name(p) << " s=" << s << " " << name(m);
      }
    EXPECT_NEAR(compute_product(f, Product::Horizon, options(2, m)).at(3, 21, 21),
                FirstStep(f, options(2, m)).floor_deg(3), 1e-6)
        << name(m);
  }
}

// Texels that are coarse positions in both axes are marched as with s = 1: every
// product is bit-identical there.
TEST(Subsample, CoarseTexelsEqualFullResolutionExactly) {
  const auto f = synthetic(39, 34);
  for (HorizonMethod m : kMethods)
  for (Product p : {Product::Horizon, Product::Skyview, Product::Shaded}) {
    const ProductBands a = compute_product(f, p, options(1, m));
    for (int s : {2, 4}) {
      const ProductBands b = compute_product(f, p, options(s, m));
      int checked = 0;
      for (int j = 0; j < f.height; ++j)
        for (int i = 0; i < f.width; ++i) {
          if (mix_of(i, f.width, s).at.size() != 1 || mix_of(j, f.height, s).at.size() != 1) continue;
          ++checked;
          for (int k = 0; k < a.bands; ++k)
            ASSERT_EQ(a.at(k, i, j), b.at(k, i, j)) << i << "," << j << " s=" << s << " " << name(m);
        }
      EXPECT_EQ(checked, ((f.width - 2) / s + 2) * ((f.height - 2) / s + 2));
    }
  }
}

// Interpolated texels: the s = 1 `horizon` values at the coarse texels they mix, where
// all are above the floor (so they are the raw σ in degrees), mixed bilinearly here and
// floored, equal the sub-sampled product.
TEST(Subsample, InterpolatedTexelsAreBilinearInRawHorizons) {
  const auto f = synthetic(39, 34);
  for (HorizonMethod m : kMethods) {
  const ProductBands full = compute_product(f, Product::Horizon, options(1, m));
  for (int s : {2, 4}) {
    const ProductBands sub = compute_product(f, Product::Horizon, options(s, m));
    const FirstStep first(f, options(s, m));
    std::size_t compared = 0, total = 0;
    double max_diff = 0.0;
    for (int j = 0; j < f.height; ++j)
      for (int i = 0; i < f.width; ++i) {
        const Mix x = mix_of(i, f.width, s), y = mix_of(j, f.height, s);
        if (x.at.size() == 1 && y.at.size() == 1) continue;
        for (int k = 0; k < full.bands; ++k) {
          ++total;
          const double fl = first.floor_deg(k);
          double sigma = 0.0;
          bool raw = true;
          for (std::size_t a = 0; a < x.at.size(); ++a)
            for (std::size_t b = 0; b < y.at.size(); ++b) {
              const double v = full.at(k, x.at[a], y.at[b]);
              raw = raw && v > static_cast<float>(fl);
              sigma += x.weight[a] * y.weight[b] * v;
            }
          if (!raw) continue;
          ++compared;
          const double d = std::abs(std::max(sigma, fl) - sub.at(k, i, j));
          max_diff = std::max(max_diff, d);
          ASSERT_LE(d, 2e-5) << "texel " << i << "," << j << " band " << k << " s=" << s << " " << name(m);
        }
      }
    std::cout << name(m) << " s=" << s << ": " << compared << " of " << total
              << " interpolated values checked, max |d| " << max_diff << " deg\n";
    EXPECT_GT(compared, total / 3);
  }
  }
}

// A nodata texel that is coarse for s = 2 and s = 4.
constexpr int kNodataI = 20, kNodataJ = 16;
terrain::HeightField with_coarse_nodata(terrain::HeightField f) {
  f.valid[static_cast<std::size_t>(kNodataJ) * f.width + kNodataI] = 0;
  return f;
}

// Where a needed coarse sample is nodata or has no step on the grid (−∞: rays leaving
// the grid at once, at the edges; found from the first step here), the march takes the
// texel's own ray: the same value as s = 1; the texels around a nodata coarse texel
// march every ray, so their svf and skyview equal s = 1's too.
TEST(Subsample, NodataAndEdgeSamplesFallBackToOwnMarch) {
  const terrain::HeightField f = with_coarse_nodata(synthetic(39, 34));
  const int ni = kNodataI, nj = kNodataJ;
  const ProductOptions o1 = options(1, HorizonMethod::March);
  const FirstStep first(f, o1);
  const ProductBands full = compute_product(f, Product::Horizon, o1);
  for (int s : {2, 4}) {
    const ProductBands sub = compute_product(f, Product::Horizon, options(s, HorizonMethod::March));
    int nodata_cases = 0, edge_cases = 0;
    for (int j = 0; j < f.height; ++j)
      for (int i = 0; i < f.width; ++i) {
        const Mix x = mix_of(i, f.width, s), y = mix_of(j, f.height, s);
        for (int k = 0; k < full.bands; ++k) {
          bool nodata = false, none = false;
          for (int ci : x.at)
            for (int cj : y.at) {
              nodata = nodata || !f.is_valid(ci, cj);
              none = none || first.unmarched(ci, cj, k);
            }
          if (!nodata && !none) continue;
          nodata_cases += nodata && f.is_valid(i, j);
          edge_cases += none && !nodata;
          const float a = full.at(k, i, j), b = sub.at(k, i, j);
          if (std::isnan(a)) {
            ASSERT_TRUE(std::isnan(b)) << i << "," << j;
          } else {
            ASSERT_EQ(a, b) << "texel " << i << "," << j << " band " << k << " s=" << s;
          }
        }
      }
    EXPECT_GE(nodata_cases, 8 * full.bands) << "s=" << s;  // the 8 neighbours, every band
    EXPECT_GT(edge_cases, 0) << "s=" << s;
    for (Product p : {Product::Svf, Product::Skyview}) {
      const ProductBands a = compute_product(f, p, o1), b = compute_product(f, p, options(s, HorizonMethod::March));
      EXPECT_TRUE(std::isnan(b.at(0, ni, nj)));
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di)
          if (di || dj) {
            EXPECT_EQ(a.at(0, ni + di, nj + dj), b.at(0, ni + di, nj + dj)) << product_name(p);
          }
    }
  }
}

// The sweep has far slopes for the coarse texels alone: where a needed coarse sample is
// nodata or −∞ it mixes the finite ones, their weights renormalised, and gives −∞ (the
// product's floor) where none is. Checked from the s = 1 `horizon` values at the coarse
// texels, where those are raw (above the floor).
TEST(Subsample, TheSweepMixesTheFiniteSamplesWhereSomeAreMissing) {
  const terrain::HeightField f = with_coarse_nodata(synthetic(39, 34));
  const ProductOptions o1 = options(1, HorizonMethod::Sweep);
  const FirstStep first(f, o1);
  const ProductBands full = compute_product(f, Product::Horizon, o1);
  for (int s : {2, 4}) {
    const ProductBands sub = compute_product(f, Product::Horizon, options(s, HorizonMethod::Sweep));
    int nodata_cases = 0, edge_cases = 0, empty_cases = 0;
    for (int j = 0; j < f.height; ++j)
      for (int i = 0; i < f.width; ++i) {
        if (!f.is_valid(i, j)) {
          EXPECT_TRUE(std::isnan(sub.at(0, i, j)));
          continue;
        }
        const Mix x = mix_of(i, f.width, s), y = mix_of(j, f.height, s);
        for (int k = 0; k < full.bands; ++k) {
          const double fl = first.floor_deg(k);
          bool nodata = false, none = false, raw = true;
          double sum = 0.0, weight = 0.0;
          for (std::size_t a = 0; a < x.at.size(); ++a)
            for (std::size_t b = 0; b < y.at.size(); ++b) {
              const int ci = x.at[a], cj = y.at[b];
              if (!f.is_valid(ci, cj) || first.unmarched(ci, cj, k)) {
                nodata = nodata || !f.is_valid(ci, cj);
                none = none || f.is_valid(ci, cj);
                continue;
              }
              const double v = full.at(k, ci, cj);
              raw = raw && v > static_cast<float>(fl);
              sum += x.weight[a] * y.weight[b] * v;
              weight += x.weight[a] * y.weight[b];
            }
          if (!nodata && !none) continue;
          if (weight == 0.0) {
            ++empty_cases;
            EXPECT_NEAR(sub.at(k, i, j), fl, 1e-5) << "texel " << i << "," << j << " band " << k << " s=" << s;
            continue;
          }
          if (!raw) continue;
          nodata_cases += nodata;
          edge_cases += none && !nodata;
          EXPECT_NEAR(sub.at(k, i, j), sum / weight, 2e-5) << "texel " << i << "," << j << " band " << k << " s=" << s;
        }
      }
    std::cout << "sweep s=" << s << ": " << nodata_cases << " beside nodata, " << edge_cases << " beside the edge, "
              << empty_cases << " with no finite sample checked\n";
    EXPECT_GE(nodata_cases, 4 * full.bands) << "s=" << s;
    EXPECT_GT(edge_cases, 0) << "s=" << s;
  }
}

struct Error {
  double rmse = 0.0, max = 0.0;
};
Error error(const ProductBands& a, const ProductBands& b) {
  Error e;
  std::size_t n = 0;
  for (std::size_t t = 0; t < a.data.size(); ++t) {
    if (std::isnan(a.data[t])) continue;
    const double d = std::abs(double(a.data[t]) - b.data[t]);
    e.rmse += d * d;
    e.max = std::max(e.max, d);
    ++n;
  }
  e.rmse = std::sqrt(e.rmse / n);
  return e;
}

// Sub-sampled svf, skyview and shaded stay close to s = 1 on rough terrain (measured
// in the header; bounds ≈ 1.3× the measurements).
TEST(Subsample, SubsampledProductsStayCloseToFullResolution) {
  const auto f = synthetic(80, 72);
  struct Bound {
    HorizonMethod m;
    Product p;
    int s;
    double rmse, max;
  };
  const Bound bounds[] = {
      {HorizonMethod::March, Product::Svf, 2, 0.055, 0.45},    {HorizonMethod::March, Product::Svf, 4, 0.077, 0.45},
      {HorizonMethod::March, Product::Skyview, 2, 0.018, 0.23}, {HorizonMethod::March, Product::Skyview, 4, 0.037, 0.36},
      {HorizonMethod::March, Product::Shaded, 2, 2.7, 30.0},    {HorizonMethod::March, Product::Shaded, 4, 5.0, 48.0},
      {HorizonMethod::Sweep, Product::Svf, 2, 0.057, 0.65},    {HorizonMethod::Sweep, Product::Svf, 4, 0.085, 0.73},
      {HorizonMethod::Sweep, Product::Skyview, 2, 0.020, 0.33}, {HorizonMethod::Sweep, Product::Skyview, 4, 0.045, 0.69},
      {HorizonMethod::Sweep, Product::Shaded, 2, 2.9, 43.0},    {HorizonMethod::Sweep, Product::Shaded, 4, 6.3, 133.0}};
  int checked = 0;
  for (HorizonMethod m : kMethods)
    for (Product p : {Product::Svf, Product::Skyview, Product::Shaded}) {
      const ProductBands full = compute_product(f, p, options(1, m));
      for (int s : {2, 4}) {
        const Error e = error(full, compute_product(f, p, options(s, m)));
        std::cout << name(m) << " " << product_name(p) << " s=" << s << " vs s=1: RMSE " << e.rmse << ", max " << e.max
                  << "\n";
        for (const Bound& b : bounds)
          if (b.m == m && b.p == p && b.s == s) {
            ++checked;
            EXPECT_LE(e.rmse, b.rmse) << product_name(p) << " s=" << s << " " << name(m);
            EXPECT_LE(e.max, b.max) << product_name(p) << " s=" << s << " " << name(m);
          }
      }
    }
  EXPECT_EQ(checked, 12);
}

}  // namespace
}  // namespace skylit::shading
