// Horizon sub-sampling on the GPU (ProductOptions::subsample; shaders/horizon_march.comp
// pass 0 finds the coarse texels' horizons, pass 1 mixes them bilinearly or takes a
// texel's own) against the CPU reference shading::compute_product with the same
// options, for s = 2 and 4, with the march and with the sweep (its far slopes swept on
// the host under llvmpipe, for the texels the passes read): horizon, svf, skyview,
// shaded and irradiance, on the synthetic test field with an extra nodata texel on the
// coarse grid (its neighbours fall back to their own horizons). Row chunks of any size
// (also fewer rows than s) give the same bands.
//
// Tolerances: gpu_products_test.cpp's and gpu_lighting_test.cpp's float32 bounds (derived
// there); the bilinear mix adds float rounding of ~1e-7 rad, far below them. The GPU and
// the CPU take the same fall-back decisions: both find −∞ by the shared edge rules
// (shading/horizon/horizon_ray.h) and nodata from the same mask.
#include "gpu_test_util.h"
#include "gpu_tolerances.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include "gpu/gpu_pipeline.h"
#include "shading/lighting.h"
#include "shading/products.h"
#include "shading/reference_pipeline.h"

namespace skylit::gpu {
namespace {

using shading::Product;
using shading::ProductBands;
using shading::ProductOptions;
using terrain::HeightField;

using namespace tolerance;  // gpu_tolerances.h

using GpuSubsampleTest = testing::GpuTest;

HeightField field_with_coarse_nodata() {
  HeightField f = testing::synthetic_field();  // nodata at (50, 40) already
  f.valid[static_cast<std::size_t>(40) * f.width + 48] = 0;  // coarse for s = 2 and 4
  return f;
}

using horizon::HorizonMethod;

ProductOptions options(int s, HorizonMethod method) {
  ProductOptions o;
  o.march.azimuths = 16;
  o.march.method = method;
  o.subsample = s;
  return o;
}

ProductOptions lit_options(int s, HorizonMethod method) {
  shading::LightingRequest r;
  r.sun_azimuth_deg = 135.0;
  r.sun_elevation_deg = 30.0;
  r.sky = "uniform";
  ProductOptions o = options(s, method);
  o.march.azimuths = 8;
  o.lighting = shading::resolve_lighting(r, std::nullopt).lighting;
  return o;
}

struct Stats {
  double max_abs = 0.0;
  double within = 0.0;  // fraction of compared values within the tolerance
  std::size_t compared = 0;
  int nan_mismatches = 0;
};

// |gpu − cpu| over every texel and band; relative: |Δ|/cpu where cpu > 0.
Stats compare(const ProductBands& gpu, const ProductBands& cpu, double tol, bool relative) {
  Stats s;
  EXPECT_EQ(gpu.bands, cpu.bands);
  EXPECT_EQ(gpu.band_names, cpu.band_names);
  if (gpu.data.size() != cpu.data.size()) {
    ADD_FAILURE() << "sizes differ";
    return s;
  }
  std::size_t ok = 0;
  for (std::size_t t = 0; t < gpu.data.size(); ++t) {
    const float g = gpu.data[t], c = cpu.data[t];
    if (std::isnan(g) || std::isnan(c)) {
      s.nan_mismatches += std::isnan(g) != std::isnan(c);
      continue;
    }
    if (relative && !(c > 0.0f)) continue;
    const double d = std::abs(static_cast<double>(g) - c) / (relative ? c : 1.0f);
    s.max_abs = std::max(s.max_abs, d);
    ++s.compared;
    ok += d <= tol;
  }
  s.within = s.compared ? static_cast<double>(ok) / s.compared : 1.0;
  return s;
}

// `host_sweep`: where the sweep's far slopes come from (the host's cores, or
// horizon_sweep.comp, as on a GPU).
void expect_matches(Product p, const ProductOptions& o, const HeightField& field, bool host_sweep = true) {
  const std::string method = o.march.method == HorizonMethod::March ? "march"
                             : host_sweep                           ? "sweep on the host"
                                                                    : "sweep in the kernel";
  SCOPED_TRACE(std::string(shading::product_name(p)) + " s=" + std::to_string(o.subsample) + " " + method);
  GpuProductPipeline pipeline(p, o);
  pipeline.set_sweeps_on_host(host_sweep);
  const ProductBands gpu = pipeline.compute(field);
  const ProductBands cpu = shading::compute_product(field, p, o);
  const bool relative = p == Product::Irradiance;
  const double tol = p == Product::Horizon ? kHorizonTolDeg
                     : p == Product::Svf   ? kSvfTol
                     : p == Product::Skyview ? kSkyviewTol
                     : relative            ? kIrradianceRelTol
                                           : kShadedTolCodes;
  const Stats s = compare(gpu, cpu, tol, relative);
  std::cout << "[ s=" << o.subsample << " " << method << " ] " << shading::product_name(p) << ": max |d|" << (relative ? " rel " : " ")
            << s.max_abs << ", within " << tol << ": " << 100.0 * s.within << "% of " << s.compared << "\n";
  EXPECT_EQ(s.nan_mismatches, 0);
  EXPECT_GT(s.compared, 0u);
  EXPECT_TRUE(std::isnan(gpu.at(0, 48, 40)));
  if (p == Product::Shaded) {
    EXPECT_GE(s.within, kMinFraction);
    EXPECT_LE(s.max_abs, kShadedMaxCodes);
  } else if (relative) {
    EXPECT_GE(s.within, kMinFraction);
  } else {
    EXPECT_LE(s.max_abs, tol);
  }
}

TEST_F(GpuSubsampleTest, ProductsMatchReference) {
  const HeightField field = field_with_coarse_nodata();
  for (HorizonMethod method : {HorizonMethod::March, HorizonMethod::Sweep})
    for (int s : {2, 4}) {
      EXPECT_TRUE(gpu_supports(Product::Shaded, options(s, method)));
      EXPECT_EQ(shading::uses_sweep(field, options(s, method)), method == HorizonMethod::Sweep);
      for (Product p : {Product::Horizon, Product::Svf, Product::Skyview, Product::Shaded})
        expect_matches(p, options(s, method), field);
      expect_matches(Product::Irradiance, lit_options(s, method), field);
      if (method == HorizonMethod::Sweep)
        for (Product p : {Product::Horizon, Product::Shaded}) expect_matches(p, options(s, method), field, false);
    }
}

// Chunks of 7 rows (rounded down to a multiple of s) and of 1 row (fewer than s: each
// chunk marches the two coarse rows bracketing it) give the whole field's bands.
TEST_F(GpuSubsampleTest, RowChunksMatchOneDispatch) {
  const HeightField field = field_with_coarse_nodata();
  for (HorizonMethod method : {HorizonMethod::March, HorizonMethod::Sweep})
    for (int s : {2, 4}) {
      GpuProductPipeline pipeline(Product::Horizon, options(s, method));
      const ProductBands whole = pipeline.compute(field);
      for (int rows : {7, 1}) {
        pipeline.set_invocations_per_dispatch(static_cast<std::size_t>(field.width) * 16 * rows);
        const ProductBands chunked = pipeline.compute(field);
        ASSERT_EQ(whole.data.size(), chunked.data.size());
        for (std::size_t t = 0; t < whole.data.size(); ++t) {
          if (std::isnan(whole.data[t]) && std::isnan(chunked.data[t])) continue;
          ASSERT_EQ(whole.data[t], chunked.data[t]) << "s=" << s << ", " << rows << "-row chunks, value " << t;
        }
      }
    }
}

TEST_F(GpuSubsampleTest, ExactWithSubsampleIsRejected) {
  ProductOptions o = options(2, HorizonMethod::March);
  o.exact = true;
  try {
    GpuProductPipeline pipeline(Product::Svf, o);
    ADD_FAILURE() << "exact with subsample 2 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "subsample does not apply to the exact march (the ground truth)");
  }
}

}  // namespace
}  // namespace skylit::gpu
