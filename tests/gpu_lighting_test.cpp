// The lit products on the GPU (shaders/sun_shadow.comp, the LIT path of
// shaders/surface_products.comp) against the CPU reference shading::compute_product
// with the same ProductOptions::lighting: `shadow`, `irradiance` and lit `shaded`, on a
// synthetic field and a real DEM crop (shared/dem, skipped if missing), sun at 10° and
// 45°, uniform and Preetham skies, and a sun below the horizon.
//
// Tolerances (float32 GPU vs double CPU): tests/gpu_tolerances.h, derivations there.
// Runs on Mesa llvmpipe where there is no GPU: W = 8, and ~20 s, most of it the
// reference's sky×BRDF tables (one per channel, built again by every compute_product).
#include "gpu_test_util.h"
#include "gpu_tolerances.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "gpu/gl_context.h"
#include "gpu/gpu_pipeline.h"
#include "shading/lighting.h"
#include "shading/products.h"
#include "shading/reference_pipeline.h"
#include "shading/shading_modes.h"
#include "shading/sky/sky_model.h"
#include "shading/sun_light.h"
#include "terrain/dem_reader.h"
#include "terrain/synthetic.h"

namespace skylit::gpu {
namespace {

using shading::Product;
using shading::ProductBands;
using shading::ProductOptions;
using terrain::HeightField;

using namespace tolerance;  // gpu_tolerances.h

using GpuLightingTest = testing::GpuTest;

using testing::synthetic_field;

using testing::real_dem;

ProductOptions lit_options(double azimuth_deg, double elevation_deg, const std::string& sky) {
  shading::LightingRequest r;
  r.sun_azimuth_deg = azimuth_deg;
  r.sun_elevation_deg = elevation_deg;
  r.sky = sky;
  ProductOptions o;
  o.march.azimuths = 8;  // the sky's W; the sun marches its own single ray
  o.lighting = shading::resolve_lighting(r, std::nullopt).lighting;
  return o;
}

struct Stats {
  double max_abs = 0.0;
  double max_rel = 0.0;      // over texels where the reference > 0
  std::size_t within = 0;    // |Δ| ≤ tol (relative: over texels where the reference > 0)
  std::size_t compared = 0;  // texels (relative: where the reference > 0)
  int nan_mismatches = 0;
  int gpu_nans_on_valid = 0;
  double fraction() const { return compared ? static_cast<double>(within) / compared : 1.0; }
};

Stats compare(const ProductBands& gpu, const ProductBands& cpu, const HeightField& field, double tol, bool relative,
              double abs_bound_all = -1.0, double rel_bound_all = 0.0) {
  Stats s;
  EXPECT_EQ(gpu.width, cpu.width);
  EXPECT_EQ(gpu.height, cpu.height);
  EXPECT_EQ(gpu.bands, cpu.bands);
  EXPECT_EQ(gpu.band_names, cpu.band_names);
  if (gpu.data.size() != cpu.data.size()) {
    ADD_FAILURE() << "sizes differ";
    return s;
  }
  int over_bound = 0;
  for (int b = 0; b < gpu.bands; ++b)
    for (int j = 0; j < gpu.height; ++j)
      for (int i = 0; i < gpu.width; ++i) {
        const float g = gpu.at(b, i, j), c = cpu.at(b, i, j);
        if (field.is_valid(i, j) && std::isnan(g)) ++s.gpu_nans_on_valid;
        if (std::isnan(g) || std::isnan(c)) {
          s.nan_mismatches += std::isnan(g) != std::isnan(c);
          continue;
        }
        const double d = std::abs(static_cast<double>(g) - c);
        s.max_abs = std::max(s.max_abs, d);
        if (abs_bound_all >= 0.0 && d > abs_bound_all + rel_bound_all * std::abs(c)) ++over_bound;
        if (relative) {
          if (!(c > 0.0f)) continue;
          const double rel = d / c;
          s.max_rel = std::max(s.max_rel, rel);
          ++s.compared;
          s.within += rel <= tol;
        } else {
          ++s.compared;
          s.within += d <= tol;
        }
      }
  EXPECT_EQ(over_bound, 0) << "texels over the all-texel bound " << abs_bound_all << " + " << rel_bound_all << "·|E|";
  return s;
}

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// GPU vs reference for one product and lighting; returns the GPU bands.
ProductBands expect_lit_matches(const GpuProductPipeline& pipeline, const HeightField& field, const std::string& label,
                                double build_ms = 0.0) {
  const Product product = pipeline.product();
  const ProductOptions& options = pipeline.options();
  SCOPED_TRACE(label + " " + std::string(shading::product_name(product)));
  GpuPipelineTimings timings;
  const ProductBands gpu = pipeline.compute(field, {}, &timings);
  const auto t0 = std::chrono::steady_clock::now();
  const ProductBands cpu = shading::compute_product(field, product, options);
  const double cpu_ms = ms_since(t0);

  const double dni = sky::luminance(options.lighting->sun.dni);
  Stats s;
  switch (product) {
    case Product::Shadow: s = compare(gpu, cpu, field, kShadowTol, false, kShadowMaxAll); break;
    case Product::Irradiance:
      s = compare(gpu, cpu, field, kIrradianceRelTol, true, kShadowTol * dni, kIrradianceRelTol);
      break;
    default: s = compare(gpu, cpu, field, kShadedTolCodes, false); break;
  }
  std::cout << "[ " << label << " ] " << shading::product_name(product) << " " << field.width << "x" << field.height
            << ": max |d| " << s.max_abs;
  if (product == Product::Irradiance) std::cout << ", max rel " << s.max_rel;
  std::cout << ", within tol " << 100.0 * s.fraction() << "% of " << s.compared << "; GPU build " << build_ms
            << " ms, compute " << timings.frame_ms << " ms (sun pass " << timings.sun_ms << " ms GPU), CPU " << cpu_ms
            << " ms\n";
  EXPECT_EQ(s.nan_mismatches, 0);
  EXPECT_EQ(s.gpu_nans_on_valid, 0);
  EXPECT_GE(s.fraction(), kMinFraction);
  if (product != Product::Irradiance) {
    EXPECT_GT(s.compared, 0u);
  }
  return gpu;
}

// Builds the pipeline once (the sky tables are the costly part) and compares it on the
// synthetic field and, when present, the real DEM crop; returns the synthetic bands.
ProductBands expect_lit_matches(Product product, const ProductOptions& options, const HeightField& synthetic,
                                const HeightField* dem, const std::string& label) {
  const auto t0 = std::chrono::steady_clock::now();
  const GpuProductPipeline pipeline(product, options);
  const double build_ms = ms_since(t0);
  ProductBands out = expect_lit_matches(pipeline, synthetic, "synthetic " + label, build_ms);
  if (dem) expect_lit_matches(pipeline, *dem, "cascades crop " + label);
  return out;
}

struct Fields {
  HeightField synthetic = synthetic_field();
  HeightField dem;
  bool have_dem = real_dem(dem);
  const HeightField* dem_or_null() const { return have_dem ? &dem : nullptr; }
};

TEST_F(GpuLightingTest, ShadowMatchesReference) {
  const Fields f;
  for (double elevation : {10.0, 45.0}) {
    const ProductOptions o = lit_options(135.0, elevation, "uniform");
    const std::string sun = "sun 135/" + std::to_string(static_cast<int>(elevation));
    const ProductBands g = expect_lit_matches(Product::Shadow, o, f.synthetic, f.dem_or_null(), sun);
    if (elevation == 10.0) {  // a low sun leaves both full shadow and full light
      const auto [lo, hi] = std::minmax_element(g.data.begin(), g.data.begin() + 1000);
      EXPECT_EQ(*lo, 0.0f);
      EXPECT_EQ(*hi, 1.0f);
    }
  }
  if (!f.have_dem) std::cout << "shared/dem/cascades_skykomish_srtm1_4326.tif missing: real DEM not compared\n";
}

TEST_F(GpuLightingTest, IrradianceAndLitShadedMatchReference) {
  const Fields f;
  for (const std::string sky : {"uniform", "preetham"})
    for (double elevation : {10.0, 45.0}) {
      const ProductOptions o = lit_options(300.0, elevation, sky);
      const std::string label = sky + " sun 300/" + std::to_string(static_cast<int>(elevation));
      // The real crop at one sun per sky (uniform 10°, Preetham 45°): the reference's
      // sky tables dominate the run time, and the field changes nothing in them.
      const bool on_dem = (sky == "uniform") == (elevation == 10.0);
      const HeightField* dem = on_dem ? f.dem_or_null() : nullptr;
      expect_lit_matches(Product::Irradiance, o, f.synthetic, dem, label);
      const ProductBands shaded = expect_lit_matches(Product::Shaded, o, f.synthetic, dem, label);
      EXPECT_EQ(shaded.bands, sky == "preetham" ? 3 : 1);
    }
}

// The sweep (shading::SunHorizon::Swept for the sun, the sky's sweep for the sky) on the
// projected synthetic field and (where ../shared is present) a geographic crop, whose
// rhumb-line sweep both run: by the GLSL kernel and on the host (a software
// rasterizer's default).
TEST_F(GpuLightingTest, SweptSunAndSkyMatchReference) {
  const Fields f;
  for (const bool on_host : {false, true})
    for (double elevation : {10.0, 45.0}) {
      ProductOptions o = lit_options(135.0, elevation, "uniform");
      o.march.method = horizon::HorizonMethod::Sweep;
      ASSERT_TRUE(shading::sun_sweeps(f.synthetic, shading::sun_shadow_options(o)));
      const std::string label = std::string(on_host ? "host-swept" : "kernel-swept") + ", sun 135/" +
                                std::to_string(static_cast<int>(elevation));
      GpuProductPipeline shadow(Product::Shadow, o), shaded(Product::Shaded, o);
      shadow.set_sweeps_on_host(on_host);
      shaded.set_sweeps_on_host(on_host);
      const ProductBands g = expect_lit_matches(shadow, f.synthetic, "synthetic " + label);
      if (f.have_dem) expect_lit_matches(shadow, f.dem, "cascades crop " + label);
      if (elevation == 10.0) {
        const auto [lo, hi] = std::minmax_element(g.data.begin(), g.data.begin() + 1000);
        EXPECT_EQ(*lo, 0.0f);
        EXPECT_EQ(*hi, 1.0f);
      }
      expect_lit_matches(shaded, f.synthetic, "synthetic " + label);
    }
}

// Sun below the horizon: no direct light (DNI 0, no shadow pass), the twilight sky only.
TEST_F(GpuLightingTest, SunBelowHorizon) {
  const HeightField field = synthetic_field();
  for (const std::string sky : {"uniform", "preetham"}) {
    const ProductOptions o = lit_options(135.0, -20.0, sky);
    ASSERT_EQ(sky::luminance(o.lighting->sun.dni), 0.0);
    expect_lit_matches(Product::Shadow, o, field, nullptr, sky + " sun 135/-20");
    const ProductBands e = expect_lit_matches(Product::Irradiance, o, field, nullptr, sky + " sun 135/-20");
    const ProductBands c = expect_lit_matches(Product::Shaded, o, field, nullptr, sky + " sun 135/-20");
    for (std::size_t t = 0; t < field.size(); ++t) {
      if (!field.valid[t]) continue;
      EXPECT_EQ(e.data[t], 0.0f) << t;
      for (int b = 0; b < c.bands; ++b) EXPECT_EQ(c.data[b * field.size() + t], 1.0f) << t;  // code 1: black
      if (HasFailure()) return;
    }
  }
}

TEST_F(GpuLightingTest, SupportAndFallbackConditions) {
  const ProductOptions lit = lit_options(315.0, 45.0, "uniform");
  for (Product p : {Product::Shadow, Product::Irradiance, Product::Shaded}) {
    EXPECT_TRUE(gpu_supports(p, lit)) << shading::product_name(p);
    ProductOptions exact = lit;
    exact.exact = true;  // the sun's exact march runs on the CPU only
    EXPECT_FALSE(gpu_supports(p, exact)) << shading::product_name(p);
    EXPECT_THROW(GpuProductPipeline(p, exact), std::invalid_argument);
  }
  ProductOptions other_mode = lit;  // every shading mode (gpu_shading_modes_test checks the SH ones)
  for (shading::ShadingMode m : {shading::ShadingMode::TripleProduct, shading::ShadingMode::LogBrdf}) {
    other_mode.shaded.mode = m;
    EXPECT_TRUE(gpu_supports(Product::Irradiance, other_mode));
    EXPECT_TRUE(gpu_supports(Product::Shaded, other_mode));
    EXPECT_TRUE(gpu_supports(Product::Shadow, other_mode));
  }
  EXPECT_FALSE(gpu_supports(Product::Shadow, ProductOptions{}));      // no lighting
  EXPECT_FALSE(gpu_supports(Product::Irradiance, ProductOptions{}));  // no lighting
  // No sky model (sun only): the sky part is left out, as the reference does.
  ProductOptions sun_only = lit_options(135.0, 30.0, "uniform");
  sun_only.lighting->sky = nullptr;
  expect_lit_matches(Product::Irradiance, sun_only, synthetic_field(), nullptr, "sun only 135/30");

  ProductOptions bad = lit;
  bad.lighting->reference_irradiance = 0.0;
  EXPECT_THROW(GpuProductPipeline(Product::Irradiance, bad), std::invalid_argument);
}

}  // namespace
}  // namespace skylit::gpu
