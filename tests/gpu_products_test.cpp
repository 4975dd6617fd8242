// The GPU product pipeline (gpu::GpuProductPipeline: shaders/horizon_march.comp,
// shaders/surface_products.comp) against the CPU reference shading::compute_product
// with the same ProductOptions, for every product (horizon, svf, skyview, shaded), on a
// synthetic field and on a real DEM crop (shared/dem, skipped if missing).
//
// Tolerances (float32 GPU vs double CPU): tests/gpu_tolerances.h, derivations there.
// Every texel is compared, edges included: both paths snap cardinal headings to exact
// zeros and count samples within horizon::edge_epsilon_texels of the last row/column.
// Runs on Mesa llvmpipe where there is no GPU.
#include "gpu_test_util.h"
#include "gpu_tolerances.h"

#include <gtest/gtest.h>

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "gpu/gl_context.h"
#include "gpu/gpu_pipeline.h"
#include "shading/horizon/azimuth.h"
#include "shading/horizon/horizon_sweep.h"
#include "shading/products.h"
#include "shading/reference_pipeline.h"
#include "terrain/dem_reader.h"
#include "terrain/synthetic.h"

namespace skylit::gpu {
namespace {

using shading::Product;
using shading::ProductBands;
using shading::ProductOptions;
using terrain::HeightField;

using namespace tolerance;  // gpu_tolerances.h

using GpuProductsTest = testing::GpuTest;

using testing::synthetic_field;

using testing::real_dem;

struct Stats {
  double max_abs = 0.0;
  double within = 0.0;  // fraction of compared values with |Δ| ≤ tol
  std::size_t compared = 0;
  int nan_mismatches = 0;
};

// |gpu − cpu| over texels at least `margin` inside the grid (default: all), all bands.
Stats compare(const ProductBands& gpu, const ProductBands& cpu, double tol, int margin = 0) {
  Stats s;
  EXPECT_EQ(gpu.width, cpu.width);
  EXPECT_EQ(gpu.height, cpu.height);
  EXPECT_EQ(gpu.bands, cpu.bands);
  EXPECT_EQ(gpu.band_names, cpu.band_names);
  if (gpu.data.size() != cpu.data.size()) {
    ADD_FAILURE() << "sizes differ";
    return s;
  }
  std::size_t ok = 0;
  for (int b = 0; b < gpu.bands; ++b)
    for (int j = margin; j < gpu.height - margin; ++j)
      for (int i = margin; i < gpu.width - margin; ++i) {
        const float g = gpu.at(b, i, j), c = cpu.at(b, i, j);
        if (std::isnan(g) || std::isnan(c)) {
          s.nan_mismatches += std::isnan(g) != std::isnan(c);
          continue;
        }
        const double d = std::abs(static_cast<double>(g) - c);
        s.max_abs = std::max(s.max_abs, d);
        ++s.compared;
        ok += d <= tol;
      }
  s.within = s.compared ? static_cast<double>(ok) / s.compared : 1.0;
  return s;
}

double tolerance(Product p) {
  switch (p) {
    case Product::Horizon: return kHorizonTolDeg;
    case Product::Svf: return kSvfTol;
    case Product::Skyview: return kSkyviewTol;
    case Product::Shaded: return kShadedTolCodes;
    default: return 0.0;
  }
}

// Runs `pipeline` and compute_product with its options on `field`; returns the GPU bands.
ProductBands expect_product_matches(const GpuProductPipeline& pipeline, const HeightField& field,
                                    const std::string& label) {
  const Product product = pipeline.product();
  const ProductOptions& options = pipeline.options();
  SCOPED_TRACE(label + " " + std::string(shading::product_name(product)));
  GpuPipelineTimings timings;
  const ProductBands gpu = pipeline.compute(field, {}, &timings);
  const auto t0 = std::chrono::steady_clock::now();
  const ProductBands cpu = shading::compute_product(field, product, options);
  const double cpu_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();

  const double tol = tolerance(product);
  const Stats s = compare(gpu, cpu, tol);
  std::cout << "[ " << label << " ] " << shading::product_name(product) << " " << field.width << "x" << field.height
            << " W=" << (product == Product::Horizon ? options.march.azimuths : options.exact ? options.exact_options.sky_azimuths : options.march.azimuths)
            << (options.exact ? " exact" : "") << ": max |d| " << s.max_abs << ", within " << tol << ": "
            << 100.0 * s.within << "% of " << s.compared << "; GPU wall " << timings.frame_ms << " ms (pyramid "
            << timings.pyramid_ms << " ms), CPU " << cpu_ms << " ms\n";
  EXPECT_EQ(s.nan_mismatches, 0);
  EXPECT_GT(s.compared, 0u);
  if (product == Product::Shaded) {
    EXPECT_GE(s.within, kMinFraction);
    EXPECT_LE(s.max_abs, kShadedMaxCodes);
  } else {
    EXPECT_LE(s.max_abs, tol);
  }
  return gpu;
}

void expect_product_matches(const HeightField& field, Product product, const ProductOptions& options,
                            const std::string& label) {
  expect_product_matches(GpuProductPipeline(product, options), field, label);
}

ProductOptions default_options() {
  ProductOptions o;
  o.march.azimuths = 16;  // W = 32 doubles the run time and tests nothing more
  return o;
}

// Each pipeline is compiled once and run on both fields (Mesa's compile of the shaded
// kernel is the slowest step on llvmpipe).
TEST_F(GpuProductsTest, AllProductsMatchReferenceOnSyntheticAndRealDem) {
  const HeightField synthetic = synthetic_field();
  HeightField dem;
  const bool have_dem = real_dem(dem);
  const ProductOptions o = default_options();
  for (Product p : {Product::Horizon, Product::Svf, Product::Skyview, Product::Shaded}) {
    const GpuProductPipeline pipeline(p, o);
    const ProductBands gpu = expect_product_matches(pipeline, synthetic, "synthetic");
    EXPECT_TRUE(std::isnan(gpu.at(0, 50, 40))) << "nodata texel, " << shading::product_name(p);
    EXPECT_FALSE(std::isnan(gpu.at(0, 51, 40))) << shading::product_name(p);
    if (have_dem) expect_product_matches(pipeline, dem, "cascades crop");
  }
  if (!have_dem) std::cout << "shared/dem/cascades_skykomish_srtm1_4326.tif missing: real DEM not compared\n";
}

// The built-in synthetic scene (30 m texels) at w × h.
HeightField synthetic_scene(int w, int h, std::uint64_t seed) {
  terrain::SyntheticOptions so;
  so.width = w;
  so.height = h;
  so.seed = seed;
  return terrain::make_synthetic_terrain(so);
}

// One pipeline, fields of one row spacing (the march variant without per-step spacing
// fetches) and of per-row spacing (a geographic grid) in turn.
TEST_F(GpuProductsTest, SwitchesBetweenOneAndPerRowSpacing) {
  const HeightField projected = synthetic_scene(60, 52, 5);
  HeightField geographic = projected;
  for (int j = 0; j < geographic.height; ++j) geographic.dx_per_row[j] = 24.0 + 0.1 * j;  // like 37–39° N at 1″
  const GpuProductPipeline pipeline(Product::Horizon, default_options());
  expect_product_matches(pipeline, projected, "one dx");
  expect_product_matches(pipeline, geographic, "per-row dx");
  expect_product_matches(pipeline, projected, "one dx again");
}

// The sweep (shading/horizon/horizon_sweep.h: horizon_sweep.comp, surface_products.comp SWEPT) against
// the reference's sweep: every product on a projected field with dx ≠ dy (both
// dominant axes, all quadrants), near steps and lines varied; a geographic field (rhumb
// lines); a field nearer a pole than the sweep takes falls back to the march in both.
TEST_F(GpuProductsTest, SweepMatchesReference) {
  HeightField field = synthetic_field();
  field.dy = 21.0;  // rays of other slopes in texel units than with square texels
  ProductOptions o = default_options();
  o.march.method = horizon::HorizonMethod::Sweep;
  for (Product p : {Product::Horizon, Product::Svf, Product::Skyview, Product::Shaded}) {
    const GpuProductPipeline pipeline(p, o);
    const ProductBands gpu = expect_product_matches(pipeline, field, "sweep");
    EXPECT_TRUE(std::isnan(gpu.at(0, 50, 40))) << "nodata texel, " << shading::product_name(p);
  }
  {  // one pipeline over fields of other sizes and back: its kept textures follow
    const GpuProductPipeline pipeline(Product::Svf, o);
    const HeightField smaller = synthetic_scene(60, 52, 5);
    for (const HeightField* f : std::initializer_list<const HeightField*>{&field, &smaller, &field})
      expect_product_matches(pipeline, *f, "sweep, kept textures");
  }
  o.march.sweep_near_steps = 0;
  o.march.sweep_lines = 3;
  o.march.curvature.radius_m = 20000.0;  // curvature that matters on a 3 km field
  expect_product_matches(field, Product::Horizon, o, "sweep K 0, 3 lines, small Earth");
  o.march.sweep_near_steps = 7;
  o.march.sweep_lines = 1;
  expect_product_matches(field, Product::Svf, o, "sweep K 7, 1 line");
  HeightField geographic = synthetic_scene(60, 52, 5);
  for (int j = 0; j < geographic.height; ++j) geographic.dx_per_row[j] = 24.0 + 0.1 * j;
  ASSERT_TRUE(shading::uses_sweep(geographic, o));
  for (Product p : {Product::Horizon, Product::Svf, Product::Shaded})
    expect_product_matches(geographic, p, o, "sweep, geographic");
  HeightField polar = geographic;
  for (int j = 0; j < polar.height; ++j) polar.dx_per_row[j] = 24.0 - 0.4 * j;  // 24 … 3.6 m
  ASSERT_FALSE(shading::uses_sweep(polar, o));
  expect_product_matches(polar, Product::Horizon, o, "sweep asked, near a pole: march");
}

// The far-slope codes themselves, GPU (float) against the reference (double): both round
// x = s/(1 + |s|) down to a code (horizon::encode_far_slope), so they differ only where
// the two roundings of the slope straddle a code boundary — by one code — and "none"
// (no far sample) must agree exactly. Products compare within tolerances far wider than a
// code (6e-5 rad), so only this test would see, say, rounding to nearest on the GPU.
// Also on rows of several spacings (rhumb lines, shading/horizon/rhumb_rows.h), where the
// kernel reads Γ and the spacings in double as the reference has them.
// Also on rows of several spacings (rhumb lines, shading/horizon/rhumb_rows.h), where the
// kernel reads Γ and the spacings in double as the reference has them; 32 headings put
// lines of both signs of r on both dominant axes.
TEST_F(GpuProductsTest, SweepFarCodesEqualTheReferenceCodes) {
  HeightField projected = synthetic_field();
  projected.dy = 21.0;
  HeightField geographic = projected;
  for (int j = 0; j < geographic.height; ++j) geographic.dx_per_row[j] = 24.0 + 0.1 * j;
  // The whole field (≈ 3.5 km across) and a bounded search, whose window the kernel
  // keeps as the host does (horizon_sweep.h).
  for (const double d : {0.0, 1000.0})
    for (const HeightField* f : {&projected, &geographic}) {
      const HeightField& field = *f;
      const std::string what = std::string(f == &projected ? "projected" : "geographic") + " D " + std::to_string(d);
      const int w = f == &projected ? 8 : 32;
      ProductOptions o = default_options();
      o.march.method = horizon::HorizonMethod::Sweep;
      o.march.azimuths = w;
      o.march.max_distance_m = d;
      ASSERT_EQ(horizon::sweep_bounded(field, o.march), d > 0.0);
      GpuProductPipeline pipeline(Product::Svf, o);
      // A software rasterizer sweeps on the host by default (the same cores, ~3.5× faster),
      // which must upload the reference's codes unchanged, each to its band's layer.
      EXPECT_EQ(pipeline.sweeps_on_host(), context->is_software());
      pipeline.set_sweeps_on_host(true);
      pipeline.compute(field);
      const std::vector<std::uint16_t> host = pipeline.far_codes();
      pipeline.set_sweeps_on_host(false);
      pipeline.compute(field);
      const std::vector<std::uint16_t> gpu = pipeline.far_codes();
      ASSERT_EQ(gpu.size(), field.size() * w);
      ASSERT_EQ(host.size(), field.size() * w);
      std::size_t equal = 0, finite = 0;
      int worst = 0;
      for (int k = 0; k < w; ++k) {
        const auto cpu = horizon::sweep_far_slopes(field, horizon::heading_from_geographic(horizon::band_azimuth(k, w)),
                                                   o.march);
        EXPECT_TRUE(std::equal(cpu.begin(), cpu.end(), host.begin() + k * field.size())) << what << " band " << k;
        for (std::size_t t = 0; t < field.size(); ++t) {
          const int g = gpu[k * field.size() + t], c = cpu[t];
          if (g == horizon::kFarCodeNone || c == horizon::kFarCodeNone) {
            EXPECT_EQ(g, c) << what << " band " << k << " texel " << t;
            continue;
          }
          ++finite;
          equal += g == c;
          worst = std::max(worst, std::abs(g - c));
        }
      }
      std::cout << "[ far codes ] " << what << ": " << finite << " finite, " << 100.0 * equal / finite
                << "% equal, worst " << worst << " code(s)\n";
      EXPECT_GT(finite, field.size() * w / 2) << what;  // most texels have a far field
      EXPECT_LE(worst, 1) << what;
      EXPECT_GE(equal, 0.98 * finite) << what;  // observed 99.8 %: float slopes err by ~1e-6, a code is 3e-5 of x
    }
}

// A sweep line holds 2·side − 1 samples in an image column: past GL_MAX_TEXTURE_SIZE the
// pipeline says so (and `auto` then computes on the reference), before any allocation.
TEST_F(GpuProductsTest, SweepBeyondTheTextureLimitFailsClearly) {
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  HeightField wide = synthetic_scene(max_size / 2 + 2, 3, 1);  // east-west lines are too long
  ProductOptions o = default_options();
  ASSERT_TRUE(shading::uses_sweep(wide, o));
  GpuProductPipeline kernel_sweep(Product::Svf, o);
  kernel_sweep.set_sweeps_on_host(false);  // the host's sweep has no such limit
  try {
    kernel_sweep.compute(wide);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("GL_MAX_TEXTURE_SIZE"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("the march method has no such limit"), std::string::npos) << e.what();
  }
}

// The march (asked for: the sweep is the default) in its settings: bilinear levels and the
// plain max (its defaults) with k_v = 2 and no curvature, no pyramid (bilinear level 0)
// with a max distance, NS09's B-spline levels and smooth max alone and together; then
// the shaded product at n = 3, N = 6, W = 12 with an albedo and exposure.
TEST_F(GpuProductsTest, MarchAndShadingVariants) {
  const HeightField field = synthetic_scene(72, 64, 11);
  ProductOptions march = default_options();
  march.march.method = horizon::HorizonMethod::March;
  ProductOptions o = march;
  o.march.curvature.enabled = false;
  o.march.k_v = 2;
  expect_product_matches(field, Product::Horizon, o, "march, k_v 2, flat Earth");
  o = march;
  o.march.use_pyramid = false;
  o.march.max_distance_m = 1000.0;  // not 900 m: see the header comment
  expect_product_matches(field, Product::Skyview, o, "no pyramid, D 1000 m");
  o = march;
  o.march.level_interpolation = terrain::Interpolation::CubicBSpline;
  expect_product_matches(field, Product::Horizon, o, "B-spline levels");
  o.march.smooth_max = true;
  expect_product_matches(field, Product::Svf, o, "B-spline levels, smooth max");
  o = march;
  o.march.smooth_max = true;
  expect_product_matches(field, Product::Horizon, o, "bilinear levels, smooth max");
  o = default_options();
  o.march.azimuths = 12;
  o.shaded.sh_order = 3;
  o.shaded.nlp_order = 6;
  o.shaded.albedo = 0.8;
  o.shaded.exposure = 1.7;
  expect_product_matches(field, Product::Shaded, o, "n 3, N 6, albedo, exposure");
}

// Row chunks (forced small here): every chunk's σ and output land in the right rows
// and bands, and progress reaches 1.
TEST_F(GpuProductsTest, RowChunksMatchOneDispatch) {
  const HeightField field = synthetic_field();
  for (Product p : {Product::Horizon, Product::Skyview}) {
    GpuProductPipeline pipeline(p, default_options());
    const ProductBands whole = pipeline.compute(field);
    pipeline.set_invocations_per_dispatch(static_cast<std::size_t>(field.width) * 16 * 7);  // 7 rows, last chunk 4
    double last = 0.0;
    int calls = 0;
    const ProductBands chunked = pipeline.compute(field, [&](double f) {
      EXPECT_GE(f, last);
      last = f;
      ++calls;
    });
    EXPECT_EQ(last, 1.0);
    EXPECT_GE(calls, 14);
    ASSERT_EQ(whole.data.size(), chunked.data.size());
    for (std::size_t t = 0; t < whole.data.size(); ++t) {
      if (std::isnan(whole.data[t]) && std::isnan(chunked.data[t])) continue;
      ASSERT_EQ(whole.data[t], chunked.data[t]) << shading::product_name(p) << " value " << t;
    }
  }
}

// options.exact: the dense exact march (shaders/horizon_exact.comp) feeds the same
// product kernel. Max distance 200 m (≤ 7 texels) with a margin of 8 texels keeps every
// sample inside the grid, where the CPU exact march and the GPU share every sample.
TEST_F(GpuProductsTest, ExactMarchProducts) {
  terrain::SyntheticOptions so;
  so.width = 40;
  so.height = 34;
  so.seed = 5;
  const HeightField field = terrain::make_synthetic_terrain(so);
  ProductOptions o;
  o.exact = true;
  o.march.azimuths = 8;
  o.march.max_distance_m = 200.0;
  o.exact_options.sky_azimuths = 16;
  for (Product p : {Product::Horizon, Product::Svf, Product::Skyview, Product::Shaded}) {
    SCOPED_TRACE(std::string(shading::product_name(p)));
    const ProductBands gpu = GpuProductPipeline(p, o).compute(field);
    const ProductBands cpu = shading::compute_product(field, p, o);
    const Stats s = compare(gpu, cpu, tolerance(p), 8);
    std::cout << "[ exact ] " << shading::product_name(p) << ": max |d| " << s.max_abs << ", within: "
              << 100.0 * s.within << "% of " << s.compared << "\n";
    EXPECT_EQ(s.nan_mismatches, 0);
    if (p == Product::Shaded) {
      EXPECT_GE(s.within, kMinFraction);
      EXPECT_LE(s.max_abs, kShadedMaxCodes);
    } else {
      EXPECT_LE(s.max_abs, tolerance(p));
    }
  }
}

// Closed forms, independent of the CPU reference: open flat ground has skyview 1 and
// svf 1; a tilted open plane (no curvature, slope s) has skyview (1 + cos s)/2.
TEST_F(GpuProductsTest, OpenPlanesMatchClosedForms) {
  HeightField flat(40, 36, 25.0);
  ProductOptions o = default_options();
  o.march.curvature.enabled = false;
  const ProductBands sky = GpuProductPipeline(Product::Skyview, o).compute(flat);
  for (float v : sky.data) ASSERT_NEAR(v, 1.0, 1e-5);
  const ProductBands svf = GpuProductPipeline(Product::Svf, o).compute(flat);
  for (float v : svf.data) ASSERT_EQ(v, 1.0f);

  HeightField tilted(40, 36, 25.0);
  const double slope = 0.3;  // rise per run, toward the east
  for (int j = 0; j < tilted.height; ++j)
    for (int i = 0; i < tilted.width; ++i) tilted.at(i, j) = static_cast<float>(100.0 + slope * 25.0 * i);
  const ProductBands t = GpuProductPipeline(Product::Skyview, o).compute(tilted);
  // The uphill half of the sky is cut by the plane itself (σ = atan(slope·cos)), which
  // the tangent plane hides anyway: skyview is the open tilted plane's (1 + cos s)/2.
  const double expected = (1.0 + std::cos(std::atan(slope))) / 2.0;
  for (int j = 2; j < tilted.height - 2; j += 5)
    for (int i = 2; i < tilted.width - 2; i += 5) ASSERT_NEAR(t.at(0, i, j), expected, 2e-3) << i << "," << j;
}

TEST_F(GpuProductsTest, RejectsBadOptionsAndLitProducts) {
  EXPECT_FALSE(gpu_supports(Product::Shadow, ProductOptions{}));
  EXPECT_FALSE(gpu_supports(Product::Irradiance, ProductOptions{}));
  EXPECT_TRUE(gpu_supports(Product::Shaded, ProductOptions{}));
  EXPECT_THROW(GpuProductPipeline(Product::Shadow, ProductOptions{}), std::invalid_argument);
  ProductOptions o;
  o.march.azimuths = 0;
  EXPECT_THROW(GpuProductPipeline(Product::Skyview, o), std::invalid_argument);
  o = ProductOptions{};
  o.shaded.exposure = 0.0;
  EXPECT_THROW(GpuProductPipeline(Product::Shaded, o), std::invalid_argument);
}

}  // namespace
}  // namespace skylit::gpu
