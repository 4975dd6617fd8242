// GPU exact horizon and sky-view factor (GpuProductPipeline with ProductOptions::exact:
// shaders/horizon_exact.comp, surface_products.comp) against
//  * a double-precision march written here from the definition (DESIGN.md "Ground
//    truth", shading/horizon/horizon_exact.h), over whole grids, edges included;
//  * the CPU reference (horizon::exact_max_elevation, shading::compute_product) on
//    texels whose rays end at the max distance before the grid edge, where the two
//    share every sample (at the edge the CPU reference currently drops samples to
//    rounding);
//  * closed forms on analytic scenes built here: flat plane (with and without Earth
//    curvature), a cylindrical pit and a long wall.
// Runs on Mesa llvmpipe where there is no GPU.
#include "gpu_test_util.h"

#include <gtest/gtest.h>

#include <chrono>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

#include "gpu/gl_context.h"
#include "gpu/gpu_pipeline.h"
#include "shading/horizon/horizon_exact.h"
#include "shading/products.h"

namespace skylit::gpu {
namespace {

using shading::Product;
using shading::ProductBands;
using terrain::HeightField;

constexpr double kDeg = 180.0 / std::numbers::pi;

// float32 vs double: heights (~1 km) carry ~6e-5 m of rounding, sample positions
// ~1e-5 texel (times slopes up to ~2), divided by the shortest lever (half a texel,
// >= 10 m here): ~2e-5 rad ~ 1e-3 deg, which is what the tests observe (<= 9.5e-4).
// The tolerance leaves a 5x margin for other drivers' atan/division.
constexpr double kHorizonTolDeg = 5e-3;
// svf = 1 − mean sin(max σ, 0): |Δsvf| ≤ |Δσ| in radians.
constexpr double kSvfTol = 1e-4;

using GpuHorizonTest = testing::GpuTest;

// One exact-march setting: W azimuths (both products) and the march itself.
struct ExactSetting {
  int azimuths = 32;
  horizon::ExactMarch march;
};

struct HorizonProducts {
  ProductBands horizon, svf;
};

// The GPU pipeline's exact horizon and svf for one setting.
HorizonProducts gpu_exact(const HeightField& field, const ExactSetting& s) {
  shading::ProductOptions o;
  o.exact = true;
  o.march.azimuths = s.azimuths;
  o.exact_options.sky_azimuths = s.azimuths;
  o.exact_options.step_texels = s.march.step_texels;
  o.march.max_distance_m = s.march.max_distance_m;
  o.march.curvature = s.march.curvature;
  return {GpuProductPipeline(Product::Horizon, o).compute(field), GpuProductPipeline(Product::Svf, o).compute(field)};
}

// Deterministic rolling relief with a sharp ridge, on rectangular texels (dx ≠ dy)
// and a non-square grid, so transposed axes or spacings cannot pass.
HeightField synthetic_field(int w, int h, double dx, double dy) {
  HeightField f(w, h, dx);
  f.dy = dy;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const double x = i * dx, y = -j * dy;
      const double rolling = 180.0 * std::sin(x / 410.0) * std::cos(y / 330.0) + 60.0 * std::sin((x + 2 * y) / 150.0);
      const double ridge = 250.0 * std::exp(-std::pow((x - 0.6 * w * dx + 0.3 * y) / 120.0, 2));
      f.at(i, j) = static_cast<float>(600.0 + rolling + ridge);
    }
  return f;
}

// The exact march from its definition, in double: from the texel centre's height,
// steps of step_texels along the ray's dominant axis (dx of the receiver's row), the
// east offset scaled by dx at the ray's mid-row (linear between rows), bilinear
// heights, curvature drop t²/(2R_eff), to max distance or the grid edge (within the
// GPU's edge epsilon), plain max of elevation angles; −∞ if there is no sample.
double reference_max_elevation(const HeightField& f, int i, int j, horizon::Heading u,
                               const horizon::ExactMarch& m) {
  const double eps = horizon::edge_epsilon_texels(f);
  const double per_m = std::max(std::abs(u.east) / f.dx(j), std::abs(u.north) / f.dy);
  const double step = m.step_texels / per_m;
  const double d_max = m.max_distance_m > 0 ? m.max_distance_m : std::hypot(f.width * f.mean_dx(), f.height * f.dy);
  const double inv_two_r = m.curvature.enabled ? 0.5 / m.curvature.effective_radius() : 0.0;
  auto row_dx = [&](double y) {
    const double yc = std::clamp(y, 0.0, f.height - 1.0);
    const int j0 = static_cast<int>(yc), j1 = std::min(j0 + 1, f.height - 1);
    return f.dx(j0) + (yc - j0) * (f.dx(j1) - f.dx(j0));
  };
  double best = -std::numeric_limits<double>::infinity();
  for (int s = 1; s * step <= d_max * (1 + 1e-9); ++s) {
    const double t = s * step;
    double y = j - t * u.north / f.dy;
    double x = i + t * u.east / row_dx(0.5 * (j + y));
    if (x < -eps || y < -eps || x > f.width - 1 + eps || y > f.height - 1 + eps) break;
    x = std::clamp(x, 0.0, f.width - 1.0);
    y = std::clamp(y, 0.0, f.height - 1.0);
    const int i0 = std::min(static_cast<int>(x), std::max(f.width - 2, 0));
    const int j0 = std::min(static_cast<int>(y), std::max(f.height - 2, 0));
    const int i1 = std::min(i0 + 1, f.width - 1), j1 = std::min(j0 + 1, f.height - 1);
    const double a = x - i0, b = y - j0;
    const double z = (1 - b) * ((1 - a) * f.at(i0, j0) + a * f.at(i1, j0)) +
                     b * ((1 - a) * f.at(i0, j1) + a * f.at(i1, j1));
    best = std::max(best, std::atan((z - t * t * inv_two_r - f.at(i, j)) / t));
  }
  return best;
}

using MarchFn = double (*)(const HeightField&, int, int, horizon::Heading, const horizon::ExactMarch&);

// The Horizon and Svf cases of shading::compute_product (reference_pipeline.cpp) in
// double precision around a given march: horizon floored at the receiver's ground
// (−atan(t₁/(2R_eff)) with curvature, else 0) in degrees; svf = 1 − mean sin(max(σ, 0)).
HorizonProducts cpu_products(const HeightField& f, const ExactSetting& o, MarchFn march) {
  const int w = o.azimuths;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  HorizonProducts out{{f.width, f.height, w, std::vector<float>(f.size() * w, nan), {}},
                  {f.width, f.height, 1, std::vector<float>(f.size(), nan), {"svf"}}};
  std::vector<double> sigma(w);
  for (int j = 0; j < f.height; ++j)
    for (int i = 0; i < f.width; ++i) {
      if (!f.is_valid(i, j)) continue;
      double sin_sum = 0.0;
      for (int k = 0; k < w; ++k) {
        const double az = 2 * std::numbers::pi * k / w;
        horizon::Heading u{std::sin(az), std::cos(az)};
        if (k * 4 % w == 0) u = {std::round(u.east), std::round(u.north)};  // N, E, S, W
        sigma[k] = march(f, i, j, u, o.march);
        const double per_m = std::max(std::abs(u.east) / f.dx(j), std::abs(u.north) / f.dy);
        const double t1 = o.march.step_texels / per_m;
        const double two_r = 2.0 * o.march.curvature.effective_radius();
        const double floor = o.march.curvature.enabled ? -std::atan(t1 / two_r) : 0.0;
        out.horizon.data[(static_cast<std::size_t>(k) * f.height + j) * f.width + i] =
            static_cast<float>(std::max(sigma[k], floor) * kDeg);
        sin_sum += std::sin(std::max(sigma[k], 0.0));
      }
      out.svf.data[static_cast<std::size_t>(j) * f.width + i] = static_cast<float>(1.0 - sin_sum / w);
    }
  return out;
}

struct Diff {
  double max_abs = 0.0;
  int nan_mismatches = 0;
};

// Largest |gpu − cpu| over texels at least `margin` texels inside the grid.
Diff compare(const ProductBands& gpu, const ProductBands& cpu, int margin = 0) {
  Diff d;
  EXPECT_EQ(gpu.width, cpu.width);
  EXPECT_EQ(gpu.height, cpu.height);
  EXPECT_EQ(gpu.bands, cpu.bands);
  if (gpu.data.size() != cpu.data.size()) {
    ADD_FAILURE() << "sizes differ";
    return d;
  }
  for (int b = 0; b < gpu.bands; ++b)
    for (int j = margin; j < gpu.height - margin; ++j)
      for (int i = margin; i < gpu.width - margin; ++i) {
        const float g = gpu.at(b, i, j), c = cpu.at(b, i, j);
        if (std::isnan(g) || std::isnan(c)) {
          d.nan_mismatches += std::isnan(g) != std::isnan(c);
          continue;
        }
        d.max_abs = std::max(d.max_abs, std::abs(static_cast<double>(g) - c));
      }
  return d;
}

// GPU vs a CPU march on one field, over texels at least `margin` inside the grid;
// returns the GPU products for further checks.
HorizonProducts expect_matches_cpu(const HeightField& field, const ExactSetting& options, MarchFn march, int margin,
                                   const char* label) {
  const auto t0 = std::chrono::steady_clock::now();
  HorizonProducts products = gpu_exact(field, options);
  const double gpu_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  const auto t1 = std::chrono::steady_clock::now();
  const HorizonProducts cpu = cpu_products(field, options, march);
  const double cpu_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t1).count();

  const Diff dh = compare(products.horizon, cpu.horizon, margin);
  const Diff ds = compare(products.svf, cpu.svf, margin);
  std::cout << "[ " << label << " ] " << field.width << "x" << field.height << " W=" << options.azimuths
            << ": max |dhorizon| " << dh.max_abs << " deg, max |dsvf| " << ds.max_abs << "; GPU " << gpu_ms
            << " ms wall (both products, kernels compiled), CPU " << cpu_ms << " ms (1 thread)\n";
  EXPECT_LE(dh.max_abs, kHorizonTolDeg) << label;
  EXPECT_LE(ds.max_abs, kSvfTol) << label;
  EXPECT_EQ(dh.nan_mismatches, 0) << label;
  EXPECT_EQ(ds.nan_mismatches, 0) << label;
  return products;
}

ExactSetting exact_options(int azimuths, double max_distance_m, bool curvature) {
  ExactSetting o;
  o.azimuths = azimuths;
  o.march.max_distance_m = max_distance_m;
  o.march.curvature.enabled = curvature;
  return o;
}

// --- against the march written here, whole grids -------------------------------

TEST_F(GpuHorizonTest, MatchesDefinitionOnSyntheticRelief) {
  const HeightField field = synthetic_field(96, 80, 30.0, 25.0);
  expect_matches_cpu(field, exact_options(16, 0.0, true), reference_max_elevation, 0, "relief");
}

TEST_F(GpuHorizonTest, MatchesDefinitionWithMaxDistanceAndNoCurvature) {
  const HeightField field = synthetic_field(64, 64, 20.0, 20.0);
  expect_matches_cpu(field, exact_options(12, 300.0, false), reference_max_elevation, 0, "max distance 300 m");
}

// Geographic DEM: dx shrinks toward the north (row 0), interpolated at the ray's
// mid-row, as in shading/horizon/horizon_ray.h.
HeightField geographic_field() {
  HeightField field = synthetic_field(64, 72, 25.0, 30.0);
  for (int j = 0; j < field.height; ++j)
    field.dx_per_row[j] = 54.0 * std::cos((60.5 - j * 0.01) * std::numbers::pi / 180.0);
  return field;
}

TEST_F(GpuHorizonTest, MatchesDefinitionWithPerRowSpacing) {
  expect_matches_cpu(geographic_field(), exact_options(8, 0.0, true), reference_max_elevation, 0, "per-row dx");
}

TEST_F(GpuHorizonTest, NodataTexelsAreNaN) {
  HeightField field = synthetic_field(32, 24, 30.0, 30.0);
  field.valid[5 * 32 + 7] = 0;
  const HorizonProducts p =
      expect_matches_cpu(field, exact_options(8, 0.0, true), reference_max_elevation, 0, "nodata");
  EXPECT_TRUE(std::isnan(p.svf.at(0, 7, 5)));
  for (int k = 0; k < 8; ++k) EXPECT_TRUE(std::isnan(p.horizon.at(k, 7, 5)));
  EXPECT_FALSE(std::isnan(p.svf.at(0, 8, 5)));
}

// --- against the CPU reference (shading/), where rays stop at the max distance -----

// 230 m reaches at most 230/20 + 1 texels: a margin of 13 keeps every sample inside.
TEST_F(GpuHorizonTest, MatchesCpuReferenceMarchInside) {
  const HeightField field = synthetic_field(72, 64, 20.0, 20.0);
  expect_matches_cpu(field, exact_options(16, 230.0, true), horizon::exact_max_elevation, 13, "CPU reference");
  expect_matches_cpu(geographic_field(), exact_options(8, 230.0, true), horizon::exact_max_elevation, 9,
                     "CPU reference, per-row dx");
}

// The public CPU entry point: same band names and layout, same values where all
// samples are inside the grid.
TEST_F(GpuHorizonTest, AgreesWithComputeProduct) {
  const HeightField field = synthetic_field(48, 40, 30.0, 25.0);
  shading::ProductOptions options;
  options.exact = true;
  options.march.azimuths = 8;
  options.march.max_distance_m = 205.0;  // ≤ 205/25 + 1 = 9 texels
  options.exact_options.sky_azimuths = 8;
  const ProductBands gpu_horizon = GpuProductPipeline(Product::Horizon, options).compute(field);
  const ProductBands gpu_svf = GpuProductPipeline(Product::Svf, options).compute(field);
  const ProductBands horizon = shading::compute_product(field, Product::Horizon, options);
  const ProductBands svf = shading::compute_product(field, Product::Svf, options);
  EXPECT_EQ(gpu_horizon.band_names, horizon.band_names);
  EXPECT_EQ(gpu_svf.band_names, svf.band_names);
  EXPECT_LE(compare(gpu_horizon, horizon, 10).max_abs, kHorizonTolDeg);
  EXPECT_LE(compare(gpu_svf, svf, 10).max_abs, kSvfTol);
}

// --- analytic scenes (independent of the CPU reference) ---------------------------

TEST_F(GpuHorizonTest, FlatPlaneIsOpenSkyAndCurvatureLowersTheHorizon) {
  const HeightField field(40, 40, 10.0);
  ExactSetting options;
  options.azimuths = 8;
  options.march.curvature.enabled = false;
  const HorizonProducts flat = gpu_exact(field, options);
  for (float v : flat.horizon.data) ASSERT_EQ(v, 0.0f);
  for (float v : flat.svf.data) ASSERT_EQ(v, 1.0f);

  // With curvature the ground falls away fastest... nowhere: the steepest sample is
  // the first, at t₁ = half a texel of the dominant axis (5 m for N/E/S/W,
  // 5·√2 m on the diagonals), so σ = −atan(t₁/(2 R_eff)) everywhere.
  options.march.curvature.enabled = true;
  const HorizonProducts curved = gpu_exact(field, options);
  const double two_r = 2.0 * options.march.curvature.effective_radius();
  for (int k = 0; k < 8; ++k) {
    const double t1 = (k % 2 ? 5.0 * std::sqrt(2.0) : 5.0);
    const double expected_deg = -std::atan(t1 / two_r) * kDeg;
    for (int j = 0; j < 40; j += 13)
      for (int i = 0; i < 40; i += 13)
        ASSERT_NEAR(curved.horizon.at(k, i, j), expected_deg, 1e-6 * std::abs(expected_deg) + 1e-9)
            << "band " << k << " texel " << i << "," << j;
  }
  for (float v : curved.svf.data) ASSERT_EQ(v, 1.0f);
}

// Cylindrical pit of radius r and depth D, seen from its centre: every direction
// sees the rim at elevation ≈ atan(D/r). Bilinear heights ramp from −D to 0 over the
// rim texel, so the exact march's maximum lies between atan(D/(r + dx·√2)) (last
// fully raised sample one diagonal texel out) and atan(D/(r − dx)) (a ramp sample).
TEST_F(GpuHorizonTest, PitCentreSeesTheRim) {
  const int n = 81;
  const double dx = 5.0, radius = 100.0, depth = 60.0;
  HeightField field(n, n, dx);
  const int c = n / 2;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (std::hypot(i - c, j - c) * dx <= radius) field.at(i, j) = static_cast<float>(-depth);
  ExactSetting options;
  options.azimuths = 24;
  options.march.curvature.enabled = false;
  const HorizonProducts p = gpu_exact(field, options);
  const double lo = std::atan(depth / (radius + dx * std::sqrt(2.0))) * kDeg;
  const double hi = std::atan(depth / (radius - dx)) * kDeg;
  double sin_sum = 0.0;
  for (int k = 0; k < options.azimuths; ++k) {
    const double sigma = p.horizon.at(k, c, c);
    EXPECT_GE(sigma, lo) << "band " << k;
    EXPECT_LE(sigma, hi) << "band " << k;
    sin_sum += std::sin(sigma / kDeg);
  }
  EXPECT_NEAR(p.svf.at(0, c, c), 1.0 - sin_sum / options.azimuths, 1e-6);
  EXPECT_LT(p.svf.at(0, c, c), 1.0 - std::sin(lo / kDeg) + 1e-6);
  // On the rim's outside the ground is flat and open toward the outside.
  EXPECT_EQ(p.horizon.at(0, c, 2), 0.0f);  // looking north from near the north edge
}

// A north–south wall of height H: from a texel at distance d east of its face, the
// western horizon (band W·3/4 = 270°) is atan(H/d) up to the ramp of bilinear
// interpolation (face between d − dx and d); east is open (exactly 0).
TEST_F(GpuHorizonTest, WallHorizonFollowsAtanHeightOverDistance) {
  const int w = 64, h = 16;
  const double dx = 10.0, wall = 50.0;
  HeightField field(w, h, dx);
  for (int j = 0; j < h; ++j)
    for (int i = 10; i <= 11; ++i) field.at(i, j) = static_cast<float>(wall);
  ExactSetting options;
  options.azimuths = 4;  // N, E, S, W
  options.march.curvature.enabled = false;
  const HorizonProducts p = gpu_exact(field, options);
  for (int i = 14; i < w; i += 7) {
    const double d_face = (i - 11) * dx;  // to the last raised texel centre
    const double sigma = p.horizon.at(3, i, h / 2);
    EXPECT_NEAR(sigma, std::atan(wall / d_face) * kDeg, 1e-3) << "column " << i;
    EXPECT_EQ(p.horizon.at(1, i, h / 2), 0.0f) << "east is open";
    EXPECT_EQ(p.horizon.at(0, i, h / 2), 0.0f) << "north runs along the wall";
    EXPECT_NEAR(p.svf.at(0, i, h / 2), 1.0 - std::sin(sigma / kDeg) / 4.0, 1e-6);
  }
}

}  // namespace
}  // namespace skylit::gpu
