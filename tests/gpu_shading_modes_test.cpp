// Wedge interpolations on the GPU (shaders/surface_products.comp, the wedge operator of
// ShadedOptions::wedge: linear, n²×2N, or cubic B-spline, n²×4N with taps j−1 … j+2 and
// the wrap-around) against the CPU reference shading::compute_product with the same
// options: unlit `shaded` (both) and lit `irradiance` (B-spline; linear is
// gpu_lighting_test's), on a small synthetic field.
//
// Tolerances (float32 GPU vs double CPU), the bounds argued in gpu_products_test and
// gpu_lighting_test, which hold for B-spline wedges unchanged: the B-spline operator
// has twice the taps, so V sums 4W instead of 2W float terms per coefficient (≤ ~2e-5
// relative instead of ~1e-5), still two decades below the bounds:
//  * shaded ≤ 1 code value on ≥ 99% of texels, ≤ 2 on all;
//  * irradiance relative ≤ 1e-3 on ≥ 99% of texels (reference > 0), and
//    |Δ| ≤ 1e-3·E + 0.02·DNI on all (the sun's shadow fraction in a penumbra).
// The two interpolations must differ by more than the tolerance somewhere, so the
// B-spline path is really taken (not the linear operator under another name).
//
// The SH shading modes (ShadedOptions::mode triple and log-brdf, shaders/
// shading_modes.glsl) against the reference the same way, unlit `shaded` and lit
// `irradiance`, with the same bounds: the triple product adds one sparse Γ product and a
// rotated ZH (a few hundred float terms per coefficient, ~1e-6 relative). The log-BRDF
// route's float HYB squares k ≤ 12 times; each squaring doubles the relative error
// of the base, so ≤ 2^k·(product rounding ~1e-6). With the sun off (DNI 0, no
// penumbra slack) the sky irradiance must match to 1e-4 relative on every texel: on
// this field ‖f̂‖ ≲ 8 (k ≤ 5, ≤ ~3e-5 for HYB); measured 3.5e-6 triple, 9.5e-6 log-brdf.
// Each mode must differ from the table mode by more than the tolerance somewhere.
#include "gpu_test_util.h"
#include "gpu_tolerances.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include "gpu/gpu_pipeline.h"
#include "gpu/shading_setup.h"
#include "shading/lighting.h"
#include "shading/products.h"
#include "shading/reference_pipeline.h"
#include "shading/sh/wedge.h"
#include "shading/shading_modes.h"
#include "shading/sky/sky_cie.h"
#include "shading/sky/sky_model.h"
#include "terrain/synthetic.h"

namespace skylit::gpu {
namespace {

using shading::Product;
using shading::ProductBands;
using shading::ProductOptions;
using sh::WedgeInterpolation;

using namespace tolerance;  // gpu_tolerances.h
constexpr double kSkyRelTol = 1e-4;  // sky-only irradiance, SH modes (argued above)

using GpuShadingModesTest = testing::GpuTest;

// 48 × 40 (W = 8 keeps the SH modes' reference runs short), nodata at (24, 20).
terrain::HeightField small_field() { return testing::synthetic_field({48, 40, 3, 1500.0, 1200.0, 24, 20}); }

ProductOptions options(WedgeInterpolation wedge, bool lit) {
  ProductOptions o;
  o.march.azimuths = 8;
  o.shaded.wedge = wedge;
  if (lit) {
    shading::LightingRequest r;
    r.sun_azimuth_deg = 135.0;
    r.sun_elevation_deg = 30.0;
    r.sky = "preetham";
    o.lighting = shading::resolve_lighting(r, std::nullopt).lighting;
  }
  return o;
}

struct Diff {
  double max_abs = 0.0, max_rel = 0.0;
  double fraction_within = 0.0;  // of compared texels
  int over_all_bound = 0, nan_mismatches = 0;
};

// |a − b| per texel; relative (reference b > 0 only) when `relative`. The all-texel
// bound is abs_all + rel_all·|b|.
Diff compare(const ProductBands& a, const ProductBands& b, double tol, bool relative, double abs_all,
             double rel_all) {
  Diff d;
  EXPECT_EQ(a.data.size(), b.data.size());
  EXPECT_EQ(a.band_names, b.band_names);
  std::size_t compared = 0, within = 0;
  for (std::size_t t = 0; t < std::min(a.data.size(), b.data.size()); ++t) {
    const double x = a.data[t], y = b.data[t];
    if (std::isnan(x) || std::isnan(y)) {
      d.nan_mismatches += std::isnan(x) != std::isnan(y);
      continue;
    }
    const double e = std::abs(x - y);
    d.max_abs = std::max(d.max_abs, e);
    d.over_all_bound += e > abs_all + rel_all * std::abs(y);
    if (relative && !(y > 0.0)) continue;
    const double r = relative ? e / y : e;
    d.max_rel = std::max(d.max_rel, relative ? r : 0.0);
    ++compared;
    within += r <= tol;
  }
  d.fraction_within = compared ? static_cast<double>(within) / compared : 0.0;
  EXPECT_GT(compared, 0u);
  return d;
}

std::string name(WedgeInterpolation w) { return w == WedgeInterpolation::Linear ? "linear" : "B-spline"; }

TEST_F(GpuShadingModesTest, WedgeInterpolationsMatchReference) {
  const terrain::HeightField field = small_field();
  ProductBands irradiance[2];
  for (WedgeInterpolation w : {WedgeInterpolation::Linear, WedgeInterpolation::BSpline}) {
    SCOPED_TRACE(name(w));
    const ProductOptions unlit = options(w, false);
    ASSERT_TRUE(gpu_supports(Product::Shaded, unlit));
    const ProductBands gpu_shaded = GpuProductPipeline(Product::Shaded, unlit).compute(field);
    const ProductBands cpu_shaded = shading::compute_product(field, Product::Shaded, unlit);
    const Diff s = compare(gpu_shaded, cpu_shaded, kShadedTolCodes, false, kShadedMaxCodes, 0.0);
    std::cout << "[ " << name(w) << " ] shaded: max |d| " << s.max_abs << " codes, within 1: "
              << 100.0 * s.fraction_within << "%\n";
    EXPECT_EQ(s.nan_mismatches, 0);
    EXPECT_EQ(s.over_all_bound, 0);
    EXPECT_GE(s.fraction_within, kMinFraction);

    const ProductOptions lit = options(w, true);
    ASSERT_TRUE(gpu_supports(Product::Irradiance, lit));
    const ProductBands gpu = GpuProductPipeline(Product::Irradiance, lit).compute(field);
    irradiance[w == WedgeInterpolation::BSpline] = gpu;
    if (w == WedgeInterpolation::Linear) continue;  // lit linear: gpu_lighting_test
    const ProductBands cpu = shading::compute_product(field, Product::Irradiance, lit);
    const double dni = sky::luminance(lit.lighting->sun.dni);
    const Diff e = compare(gpu, cpu, kIrradianceRelTol, true, kShadowTol * dni, kIrradianceRelTol);
    std::cout << "[ " << name(w) << " ] irradiance: max |d| " << e.max_abs << " W/m^2, max rel " << e.max_rel
              << ", within 1e-3: " << 100.0 * e.fraction_within << "%\n";
    EXPECT_EQ(e.nan_mismatches, 0);
    EXPECT_EQ(e.over_all_bound, 0);
    EXPECT_GE(e.fraction_within, kMinFraction);
  }
  const Diff between = compare(irradiance[1], irradiance[0], kIrradianceRelTol, true, 1e300, 0.0);
  std::cout << "B-spline vs linear irradiance (GPU): max rel " << between.max_rel << "\n";
  EXPECT_GT(between.max_rel, 10.0 * kIrradianceRelTol);
}

TEST_F(GpuShadingModesTest, ShModesMatchReference) {
  const terrain::HeightField field = small_field();
  const ProductOptions table_lit = options(WedgeInterpolation::Linear, true);
  const ProductBands table_irradiance = GpuProductPipeline(Product::Irradiance, table_lit).compute(field);
  for (shading::ShadingMode mode : {shading::ShadingMode::TripleProduct, shading::ShadingMode::LogBrdf}) {
    const std::string mode_name(shading::to_string(mode));
    SCOPED_TRACE(mode_name);
    ProductOptions unlit = options(WedgeInterpolation::Linear, false);
    unlit.shaded.mode = mode;
    ASSERT_TRUE(gpu_supports(Product::Shaded, unlit));
    const ProductBands gpu_shaded = GpuProductPipeline(Product::Shaded, unlit).compute(field);
    const ProductBands cpu_shaded = shading::compute_product(field, Product::Shaded, unlit);
    const Diff s = compare(gpu_shaded, cpu_shaded, kShadedTolCodes, false, kShadedMaxCodes, 0.0);
    std::cout << "[ " << mode_name << " ] shaded: max |d| " << s.max_abs << " codes, within 1: "
              << 100.0 * s.fraction_within << "%\n";
    EXPECT_EQ(s.nan_mismatches, 0);
    EXPECT_EQ(s.over_all_bound, 0);
    EXPECT_GE(s.fraction_within, kMinFraction);

    ProductOptions lit = table_lit;
    lit.shaded.mode = mode;
    ASSERT_TRUE(gpu_supports(Product::Irradiance, lit));
    const ProductBands gpu = GpuProductPipeline(Product::Irradiance, lit).compute(field);
    const ProductBands cpu = shading::compute_product(field, Product::Irradiance, lit);
    const double dni = sky::luminance(lit.lighting->sun.dni);
    const Diff e = compare(gpu, cpu, kIrradianceRelTol, true, kShadowTol * dni, kIrradianceRelTol);
    std::cout << "[ " << mode_name << " ] irradiance: max |d| " << e.max_abs << " W/m^2, max rel " << e.max_rel
              << ", within 1e-3: " << 100.0 * e.fraction_within << "%\n";
    EXPECT_EQ(e.nan_mismatches, 0);
    EXPECT_EQ(e.over_all_bound, 0);
    EXPECT_GE(e.fraction_within, kMinFraction);
    // Sky alone (DNI 0): the SH shading without the shadow's penumbra slack.
    ProductOptions sky_only = lit;
    sky_only.lighting->sun.dni = sky::Rgb(0.0);
    const Diff k = compare(GpuProductPipeline(Product::Irradiance, sky_only).compute(field),
                           shading::compute_product(field, Product::Irradiance, sky_only), kSkyRelTol, true, 0.0,
                           kSkyRelTol);
    std::cout << "[ " << mode_name << " ] sky-only irradiance: max |d| " << k.max_abs << " W/m^2, max rel "
              << k.max_rel << "\n";
    EXPECT_EQ(k.nan_mismatches, 0);
    EXPECT_EQ(k.over_all_bound, 0);
    // Colour `shaded` (one sky SH per channel R, G, B): codes, as unlit.
    ProductOptions colour = lit;
    colour.lighting->colour = true;
    const Diff c = compare(GpuProductPipeline(Product::Shaded, colour).compute(field),
                           shading::compute_product(field, Product::Shaded, colour), kShadedTolCodes, false,
                           kShadedMaxCodes, 0.0);
    std::cout << "[ " << mode_name << " ] colour shaded: max |d| " << c.max_abs << " codes, within 1: "
              << 100.0 * c.fraction_within << "%\n";
    EXPECT_EQ(c.nan_mismatches, 0);
    EXPECT_EQ(c.over_all_bound, 0);
    EXPECT_GE(c.fraction_within, kMinFraction);
    const Diff vs_table = compare(gpu, table_irradiance, kIrradianceRelTol, true, 1e300, 0.0);
    std::cout << "[ " << mode_name << " ] vs table irradiance (GPU): max rel " << vs_table.max_rel << "\n";
    EXPECT_GT(vs_table.max_rel, 10.0 * kIrradianceRelTol);
  }
}

// The uploaded tables are the reference's (SkyShading, LitShading), texel for texel,
// built with the sky's symmetry flag (a z-symmetric sky's rows are rotated, which
// moves near-zenith entries by ~1e-6: too little for the image comparisons to notice).
TEST(ShadingSetup, TablesUseTheSkysSymmetryFlag) {
  const auto table = [](const shading::Radiance& sky, bool z_symmetric) {
    const shading::SkyBrdfTable t(sh::kDefaultOrder, 1.0, sky, shading::AxisGrid::hemisphere(), {}, z_symmetric);
    return std::vector<float>(t.texels().begin(), t.texels().end());
  };
  const auto uploaded = [](const ProductOptions& o) {
    GlslDefines d;
    return shading_setup(Product::Shaded, o, 0, 1, d).sky;
  };
  ProductOptions o;
  EXPECT_EQ(uploaded(o), table(shading::uniform_sky_radiance(), true));
  const glm::dvec3 sun = sky::direction_from_azimuth_elevation(2.0, 0.5);
  for (int type : {16, 12}) {
    o.lighting = shading::Lighting{std::make_shared<sky::CieSky>(type, sun, sky::Rgb(1.0)), {sun, sky::Rgb(0.0)}};
    EXPECT_EQ(uploaded(o), table(shading::channel_radiance(o.lighting->sky, false, 0), type == 16)) << type;
  }
}

}  // namespace
}  // namespace skylit::gpu
