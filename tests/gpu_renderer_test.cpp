// The GPU renderer (gpu/gpu_renderer.h) and the library's backend choice
// (gpu/renderer_factory.h): frames of a series equal a fresh GpuProductPipeline built
// for each frame's lighting bit for bit, though later frames reuse the kept visibility
// and compile nothing; an edit recomputes; a change in the lighting's shape (colour, sun
// below the horizon) gets its own kernels; auto takes the reference where the GPU lacks
// the product. Runs on Mesa llvmpipe where there is no GPU.
#include "lighting_test_util.h"
#include "gpu_test_util.h"
#include "gpu_tolerances.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "gpu/gpu_pipeline.h"
#include "gpu/gpu_renderer.h"
#include "gpu/renderer_factory.h"
#include "shading/lighting.h"
#include "shading/products.h"
#include "terrain/editing.h"

namespace skylit::gpu {
namespace {

using ::skylit::testing::sun_at;  // lighting_test_util.h

using shading::FrameInputs;
using shading::Lighting;
using shading::Product;
using shading::ProductBands;
using shading::ProductOptions;

using GpuRendererTest = testing::GpuTest;

ProductOptions small_options() {
  ProductOptions o;
  o.march.azimuths = 8;
  return o;
}

bool bit_identical(const ProductBands& a, const ProductBands& b) {
  return a.width == b.width && a.height == b.height && a.bands == b.bands && a.band_names == b.band_names &&
         a.data.size() == b.data.size() && std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)) == 0;
}

// A renderer on `f` with these options, told to expect `frames` frames.
std::unique_ptr<GpuRenderer> renderer_on(const terrain::HeightField& f, const ProductOptions& o, int frames) {
  auto r = std::make_unique<GpuRenderer>();
  r->set_field(f);
  r->set_options(o);
  r->expect_frames(frames);
  return r;
}

// A pipeline built for this one frame, on the renderer's context.
ProductBands fresh(GpuRenderer& r, const terrain::HeightField& f, Product p, ProductOptions o, const Lighting& l) {
  r.context().make_current();
  o.lighting = l;
  return GpuProductPipeline(p, o).compute(f);
}

TEST_F(GpuRendererTest, SeriesFramesEqualFreshPipelinesAndReuseTheVisibility) {
  const terrain::HeightField f = testing::synthetic_field();
  const ProductOptions o = small_options();
  const auto renderer = renderer_on(f, o, 3);
  GpuRenderer& r = *renderer;
  const Lighting suns[] = {sun_at(90, 10), sun_at(180, 50), sun_at(270, 25)};
  bool first = true;  // the renderer's first frame reports its context's creation
  for (Product p : {Product::Irradiance, Product::Shaded, Product::Shadow}) {
    for (int k = 0; k < 3; ++k) {
      const ProductBands got = r.frame(p, {suns[k], {}, std::nullopt});
      const shading::FrameTimings t = r.last_timings();
      EXPECT_EQ(t.context_ms > 0.0, first) << shading::product_name(p) << " frame " << k;
      first = false;
      if (p != Product::Shadow) {
        EXPECT_EQ(t.horizons_reused, k > 0) << shading::product_name(p) << " frame " << k;
      }
      if (k > 0) {
        EXPECT_EQ(t.compile_ms, 0.0) << shading::product_name(p) << " frame " << k;
        EXPECT_EQ(t.uploaded_bytes, 0u) << shading::product_name(p) << " frame " << k;
      }
      EXPECT_TRUE(bit_identical(got, fresh(r, f, p, o, suns[k]))) << shading::product_name(p) << " frame " << k;
    }
  }
}

// Aircraft move every frame: a blocked series keeps the terrain's visibility and its
// floored horizons (the spheres' horizon cull) and equals fresh blocked pipelines.
TEST_F(GpuRendererTest, BlockedSeriesFramesEqualFreshPipelinesAndReuseTheHorizons) {
  const terrain::HeightField f = testing::synthetic_field();
  const ProductOptions o = small_options();
  const auto renderer = renderer_on(f, o, 3);
  GpuRenderer& r = *renderer;
  const Lighting sun = sun_at(135, 30, "preetham");
  const double dx = f.mean_dx(), dy = f.dy;
  for (Product p : {Product::Shaded, Product::Irradiance}) {
    for (int k = 0; k < 3; ++k) {
      // A low sphere whose sky cap is partly behind the terrain from nearby texels, so
      // the horizon cull decides texels.
      const std::vector<blockers::Sphere> spheres = {{{(20.0 + 8 * k) * dx, -(30.0 + 5 * k) * dy, f.at(20 + 8 * k, 30 + 5 * k) + 60.0}, 40.0},
                                                     {{40.0 * dx, -(10.0 + 10 * k) * dy, 2500.0}, 80.0}};
      const ProductBands got = r.frame(p, {sun, spheres, std::nullopt});
      EXPECT_EQ(r.last_timings().horizons_reused, k > 0) << shading::product_name(p) << " frame " << k;
      r.context().make_current();
      ProductOptions lit = o;
      lit.lighting = sun;
      GpuProductPipeline one(p, lit, true);
      one.set_spheres(spheres);
      EXPECT_TRUE(bit_identical(got, one.compute(f))) << shading::product_name(p) << " frame " << k;
    }
  }
}

// A replay's track has gaps: told to expect blockers, the renderer shades a frame
// without spheres with the blocked kernels, keeping the horizons on both sides of it,
// and the frame equals the terrain's alone (a fresh pipeline without blockers) bit for bit.
TEST_F(GpuRendererTest, AFrameWithoutTheExpectedSpheresKeepsTheHorizons) {
  const terrain::HeightField f = testing::synthetic_field();
  const ProductOptions o = small_options();
  const Lighting sun = sun_at(135, 30, "preetham");
  const double dx = f.mean_dx(), dy = f.dy;
  const std::vector<blockers::Sphere> spheres = {{{40.0 * dx, -30.0 * dy, f.at(40, 30) + 80.0}, 40.0}};
  for (Product p : {Product::Shaded, Product::Irradiance, Product::Shadow}) {
    for (const bool expected : {false, true}) {
      const auto renderer = renderer_on(f, o, 3);
      GpuRenderer& r = *renderer;
      r.expect_blockers(expected);
      r.frame(p, {sun, spheres, std::nullopt});
      const ProductBands gap = r.frame(p, {sun, {}, std::nullopt});
      const bool gap_kept = r.last_timings().horizons_reused;
      r.frame(p, {sun, spheres, std::nullopt});
      const bool after_kept = r.last_timings().horizons_reused;
      const std::string what = std::string(shading::product_name(p)) + (expected ? ", expected" : ", unexpected");
      if (p != Product::Shadow) {  // shadow keeps no horizons
        EXPECT_EQ(gap_kept, expected) << what;
        EXPECT_TRUE(after_kept) << what;
      }
      EXPECT_TRUE(bit_identical(gap, fresh(r, f, p, o, sun))) << what;
    }
  }
}

TEST_F(GpuRendererTest, AFrameAfterAnEditRecomputesTheVisibility) {
  terrain::HeightField f = testing::synthetic_field();
  const ProductOptions o = small_options();
  const auto renderer = renderer_on(f, o, 2);
  GpuRenderer& r = *renderer;
  const Lighting sun = sun_at(135, 30);
  r.frame(Product::Irradiance, {sun, {}, std::nullopt});
  const terrain::PixelRect edit{20, 30, 10, 6};
  std::vector<float> raised;
  for (int j = edit.y0; j < edit.y1(); ++j)
    for (int i = edit.x0; i < edit.x1(); ++i) raised.push_back(f.at(i, j) + 400.0f);
  terrain::replace_heights(f, edit, raised);
  const ProductBands after = r.frame(Product::Irradiance, {sun, {}, std::nullopt});
  EXPECT_FALSE(r.last_timings().horizons_reused);
  EXPECT_GT(r.last_timings().uploaded_bytes, 0u);
  EXPECT_TRUE(bit_identical(after, fresh(r, f, Product::Irradiance, o, sun)));
}

TEST_F(GpuRendererTest, ALightingOfAnotherShapeGetsItsOwnKernels) {
  const terrain::HeightField f = testing::synthetic_field();
  const ProductOptions o = small_options();
  const auto renderer = renderer_on(f, o, 3);
  GpuRenderer& r = *renderer;
  const Lighting grey = sun_at(120, 35), colour = sun_at(120, 35, "preetham"), night = sun_at(120, -5);
  ASSERT_TRUE(colour.colour && !grey.colour);
  for (const Lighting& l : {grey, colour, night}) {
    const ProductBands got = r.frame(Product::Shaded, {l, {}, std::nullopt});
    EXPECT_EQ(got.bands, l.colour ? 3 : 1);
    EXPECT_TRUE(bit_identical(got, fresh(r, f, Product::Shaded, o, l)));
  }
}

TEST_F(GpuRendererTest, AnotherToneOrExposureOnTheSamePipelineCodesWithIt) {
  // Neither is baked into the kernels, so the cached pipeline serves them: each frame must
  // still code with its own, as a pipeline built for it does.
  const terrain::HeightField f = testing::synthetic_field();
  const Lighting l = sun_at(120, 35, "preetham");
  ProductOptions o = small_options();
  const auto renderer = renderer_on(f, o, 3);
  GpuRenderer& r = *renderer;
  for (const auto& [tone, exposure] : {std::pair{shading::ToneCurve::Srgb, 1.0}, {shading::ToneCurve::Linear, 1.0},
                                       {shading::ToneCurve::Linear, 0.5}}) {
    o.shaded.tone = tone;
    o.shaded.exposure = exposure;
    r.set_options(o);
    const ProductBands got = r.frame(Product::Shaded, {l, {}, std::nullopt});
    EXPECT_TRUE(bit_identical(got, fresh(r, f, Product::Shaded, o, l)))
        << (tone == shading::ToneCurve::Srgb ? "srgb" : "linear") << ", exposure " << exposure;
  }
}

TEST_F(GpuRendererTest, SeriesFramesMatchTheReference) {
  const terrain::HeightField f = testing::synthetic_field();
  const ProductOptions o = small_options();
  const auto renderer = renderer_on(f, o, 2);
  GpuRenderer& r = *renderer;
  const Lighting sun = sun_at(300, 20);
  r.frame(Product::Irradiance, {sun_at(60, 40), {}, std::nullopt});
  const ProductBands gpu = r.frame(Product::Irradiance, {sun, {}, std::nullopt});
  ASSERT_TRUE(r.last_timings().horizons_reused);
  ProductOptions lit = o;
  lit.lighting = sun;
  const ProductBands cpu = shading::compute_product(f, Product::Irradiance, lit);
  std::size_t within = 0, compared = 0;
  const double dni = sky::luminance(sun.sun.dni);
  for (std::size_t k = 0; k < cpu.data.size(); ++k) {
    if (std::isnan(cpu.data[k])) continue;
    ++compared;
    const double diff = std::abs(gpu.data[k] - cpu.data[k]);
    EXPECT_LE(diff, tolerance::kIrradianceRelTol * std::abs(cpu.data[k]) + 0.02 * dni) << "texel " << k;
    within += diff <= tolerance::kIrradianceRelTol * std::abs(cpu.data[k]);
  }
  EXPECT_GE(static_cast<double>(within) / compared, tolerance::kMinFraction);
}

TEST_F(GpuRendererTest, AutoTakesTheReferenceWhereTheGpuLacksTheProduct) {
  const terrain::HeightField f = testing::synthetic_field({.width = 24, .height = 20, .nodata_i = 3, .nodata_j = 4});
  std::vector<std::string> notes;
  const auto r = make_renderer(Backend::Auto, [&](const std::string& n) { notes.push_back(n); });
  ProductOptions o = small_options();
  r->set_field(f);
  r->set_options(o);
  r->frame(Product::Svf, {});
  EXPECT_TRUE(r->on_gpu());
  EXPECT_EQ(r->description().rfind("gpu (", 0), 0u) << r->description();
  o.exact = true;  // the sun's exact march is CPU-only
  o.exact_options.sky_azimuths = 16;
  r->set_options(o);
  r->frame(Product::Shadow, {sun_at(200, 15), {}, std::nullopt});
  EXPECT_FALSE(r->on_gpu());
  EXPECT_EQ(r->description(), "reference (CPU; the GPU pipeline lacks these options)");
  EXPECT_TRUE(notes.empty());
  const auto gpu = make_renderer(Backend::Gpu);
  gpu->set_field(f);
  gpu->set_options(o);
  EXPECT_THROW(gpu->frame(Product::Shadow, {sun_at(200, 15), {}, std::nullopt}), std::invalid_argument);
  EXPECT_TRUE(gpu->lacks(Product::Shadow, shading::frame_options(o, {sun_at(200, 15), {}, std::nullopt})));
}

// Frames left on the GPU hold what frame() reads back: the same floats, and for
// `shaded` the linear values its tone map turns into the same codes.
TEST_F(GpuRendererTest, FramesOnTheGpuHoldWhatFrameReadsBack) {
  const terrain::HeightField f = testing::synthetic_field();
  const auto renderer = renderer_on(f, small_options(), 2);
  GpuRenderer& r = *renderer;
  const Lighting sun = sun_at(225, 30, "preetham");
  for (Product p : {Product::Skyview, Product::Shadow, Product::Irradiance, Product::Shaded}) {
    const ProductBands host = r.frame(p, {sun, {}, std::nullopt});
    const GpuFrame device = r.frame_on_gpu(p, {sun, {}, std::nullopt});
    ASSERT_EQ(device.band_count, host.bands) << shading::product_name(p);
    ASSERT_EQ(device.width, host.width);
    const std::vector<float> values = device.bands.download_all<float>();
    ASSERT_EQ(values.size(), host.data.size());
    for (std::size_t t = 0; t < values.size(); ++t) {
      if (std::isnan(host.data[t])) {
        EXPECT_TRUE(std::isnan(values[t])) << shading::product_name(p) << " " << t;
        continue;
      }
      const float v = p == Product::Shaded ? shading::srgb_code_value(values[t] * device.display_scale) : values[t];
      ASSERT_EQ(v, host.data[t]) << shading::product_name(p) << " texel " << t;
    }
  }
}

}  // namespace
}  // namespace skylit::gpu
