// Horizon sub-sampling in the CPU reference (ProductOptions::subsample, products.h):
// raw horizons marched at the coarse texels (0, s, 2s, … and the last index per axis),
// bilinear elsewhere, a texel's own march where a needed coarse sample is nodata or −∞.
// Checked against independent derivations: the coarse grid restated here (not
// horizon::SubsampleAxis), bilinear mixes of the s = 1 `horizon` product computed in the
// test, −∞ samples found with HorizonMarcher directly, and the closed forms of a tilted
// plane.
//
// Measured (printed below) on the 80×72 synthetic scene (30 m texels, 1200 m relief in
// 2 km features: horizons change a lot from texel to texel, since the first steps lie
// within a texel or two), W = 16, vs s = 1, RMSE (max):
//   s = 2: svf 0.043 (0.34), skyview 0.014 (0.17), shaded 2.0 codes (23)
//   s = 4: svf 0.059 (0.34), skyview 0.028 (0.27), shaded 3.8 codes (37)
// SubsampledProductsStayCloseToFullResolution bounds them at ≈ 1.3× those.
#include "horizon_scenes.h"

#include "shading/horizon/azimuth.h"
#include "shading/horizon/horizon_march.h"
#include "shading/products.h"
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

// The march's sub-sampling (s = 1 too: the default sweep does not sub-sample).
ProductOptions options(int s, int azimuths = 16) {
  ProductOptions o;
  o.march.method = horizon::HorizonMethod::March;
  o.march.azimuths = azimuths;
  o.subsample = s;
  return o;
}

// The `horizon` product's floor (degrees): the receiver's ground at the first march
// distance, −atan(t₁/(2R_eff)) (products.h).
double floor_deg(const terrain::HeightField& f, const ProductOptions& o) {
  const double t1 = horizon::HorizonMarcher(f, o.march).distance(0);
  return -std::atan(t1 / (2.0 * o.march.curvature.effective_radius())) * kDeg;
}

TEST(Subsample, Validation) {
  const auto f = terrain::flat_plane(8, 8, 10.0);
  ProductOptions o;
  o.subsample = 3;
  EXPECT_THROW(compute_product(f, Product::Svf, o), std::invalid_argument);
  o.subsample = 2;
  o.exact = true;
  try {
    compute_product(f, Product::Svf, o);
    ADD_FAILURE() << "exact with subsample 2 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "subsample needs the multi-resolution march (not the exact march)");
  }
}

// Open flat ground with Earth curvature: σ_k = −atan(t₀/(2R_eff)) at every texel whose
// first step lies on the grid (−∞ otherwise, which falls back to the texel's own
// march), so the bilinear mixes are exact and every product equals s = 1.
TEST(Subsample, FlatGroundEqualsFullResolution) {
  const auto f = terrain::flat_plane(45, 41, 25.0);
  for (int s : {2, 4})
    for (Product p : {Product::Horizon, Product::Svf, Product::Skyview, Product::Shaded}) {
      const ProductBands a = compute_product(f, p, options(1)), b = compute_product(f, p, options(s));
      double max_diff = 0.0;
      for (std::size_t t = 0; t < a.data.size(); ++t)
        max_diff = std::max(max_diff, std::abs(double(a.data[t]) - b.data[t]));
      EXPECT_LE(max_diff, 1e-9) << product_name(p) << " s=" << s;
    }
  EXPECT_NEAR(compute_product(f, Product::Horizon, options(2)).at(3, 21, 21), floor_deg(f, options(2)), 1e-6);
}

// Texels that are coarse positions in both axes are marched as with s = 1: every
// product is bit-identical there.
TEST(Subsample, CoarseTexelsEqualFullResolutionExactly) {
  const auto f = synthetic(39, 34);
  for (Product p : {Product::Horizon, Product::Skyview, Product::Shaded}) {
    const ProductBands a = compute_product(f, p, options(1));
    for (int s : {2, 4}) {
      const ProductBands b = compute_product(f, p, options(s));
      int checked = 0;
      for (int j = 0; j < f.height; ++j)
        for (int i = 0; i < f.width; ++i) {
          if (mix_of(i, f.width, s).at.size() != 1 || mix_of(j, f.height, s).at.size() != 1) continue;
          ++checked;
          for (int k = 0; k < a.bands; ++k) ASSERT_EQ(a.at(k, i, j), b.at(k, i, j)) << i << "," << j << " s=" << s;
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
  const ProductBands full = compute_product(f, Product::Horizon, options(1));
  for (int s : {2, 4}) {
    const ProductBands sub = compute_product(f, Product::Horizon, options(s));
    const double fl = floor_deg(f, options(s));
    std::size_t compared = 0, total = 0;
    double max_diff = 0.0;
    for (int j = 0; j < f.height; ++j)
      for (int i = 0; i < f.width; ++i) {
        const Mix x = mix_of(i, f.width, s), y = mix_of(j, f.height, s);
        if (x.at.size() == 1 && y.at.size() == 1) continue;
        for (int k = 0; k < full.bands; ++k) {
          ++total;
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
          ASSERT_LE(d, 2e-5) << "texel " << i << "," << j << " band " << k << " s=" << s;
        }
      }
    std::cout << "s=" << s << ": " << compared << " of " << total << " interpolated values checked, max |d| "
              << max_diff << " deg\n";
    EXPECT_GT(compared, total / 3);
  }
}

// Where a needed coarse sample is nodata or has no step on the grid (−∞: rays leaving
// the grid at once, at the edges; found with HorizonMarcher here), the texel marches its
// own ray: the same value as s = 1. The texels around a nodata coarse texel march every
// ray, so their svf and skyview equal s = 1's too.
TEST(Subsample, NodataAndEdgeSamplesFallBackToOwnMarch) {
  auto f = synthetic(39, 34);
  const int ni = 20, nj = 16;  // a coarse texel for s = 2 and s = 4
  f.valid[static_cast<std::size_t>(nj) * f.width + ni] = 0;
  const ProductOptions o1 = options(1);
  const horizon::HorizonMarcher marcher(f, o1.march);
  const ProductBands full = compute_product(f, Product::Horizon, o1);
  for (int s : {2, 4}) {
    const ProductBands sub = compute_product(f, Product::Horizon, options(s));
    int nodata_cases = 0, edge_cases = 0;
    for (int j = 0; j < f.height; ++j)
      for (int i = 0; i < f.width; ++i) {
        const Mix x = mix_of(i, f.width, s), y = mix_of(j, f.height, s);
        for (int k = 0; k < full.bands; ++k) {
          const horizon::Heading u = horizon::heading_from_geographic(horizon::band_azimuth(k, full.bands));
          bool nodata = false, unmarched = false;
          for (int ci : x.at)
            for (int cj : y.at) {
              nodata = nodata || !f.is_valid(ci, cj);
              unmarched = unmarched || marcher.max_elevation(ci, cj, u) == -std::numeric_limits<double>::infinity();
            }
          if (!nodata && !unmarched) continue;
          nodata_cases += nodata && f.is_valid(i, j);
          edge_cases += unmarched && !nodata;
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
      const ProductBands a = compute_product(f, p, o1), b = compute_product(f, p, options(s));
      EXPECT_TRUE(std::isnan(b.at(0, ni, nj)));
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di)
          if (di || dj) {
            EXPECT_EQ(a.at(0, ni + di, nj + dj), b.at(0, ni + di, nj + dj)) << product_name(p);
          }
    }
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
    Product p;
    int s;
    double rmse, max;
  };
  const Bound bounds[] = {{Product::Svf, 2, 0.055, 0.45},    {Product::Svf, 4, 0.077, 0.45},
                          {Product::Skyview, 2, 0.018, 0.23}, {Product::Skyview, 4, 0.037, 0.36},
                          {Product::Shaded, 2, 2.7, 30.0},    {Product::Shaded, 4, 5.0, 48.0}};
  for (Product p : {Product::Svf, Product::Skyview, Product::Shaded}) {
    const ProductBands full = compute_product(f, p, options(1));
    for (int s : {2, 4}) {
      const Error e = error(full, compute_product(f, p, options(s)));
      std::cout << product_name(p) << " s=" << s << " vs s=1: RMSE " << e.rmse << ", max " << e.max << "\n";
      for (const Bound& b : bounds)
        if (b.p == p && b.s == s) {
          EXPECT_LE(e.rmse, b.rmse) << product_name(p) << " s=" << s;
          EXPECT_LE(e.max, b.max) << product_name(p) << " s=" << s;
        }
    }
  }
}

}  // namespace
}  // namespace skylit::shading
