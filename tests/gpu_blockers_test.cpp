// Sphere blockers on the GPU (gpu/gpu_blockers.h, shaders/sphere_blockers.glsl,
// blocker_sun.comp) against the CPU reference's (shading/blocker_frame.h) on the same
// field, spheres and options: skyview, shaded in each shading mode, irradiance and
// shadow, within the float tolerances of gpu_tolerances.h, and the change the spheres
// make captured (not only the terrain's bands matched).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "gpu/gpu_renderer.h"
#include "gpu_test_util.h"
#include "gpu_tolerances.h"
#include "shading/lighting.h"
#include "shading/reference_renderer.h"
#include "terrain/synthetic.h"

namespace skylit::gpu {
namespace {

using shading::Product;
using shading::ProductBands;
using shading::ProductOptions;

class GpuBlockers : public testing::GpuTest {};

using testing::sun_at;

terrain::HeightField hills() { return testing::hills(72, 64); }

// Two sets of spheres over the hills: an aircraft 40 m up (a wide soft sky shadow), and
// a chain of overlapping spheres 25 m up whose penumbrae overlap on the sun disc (the
// union sampled).
std::vector<blockers::Sphere> aircraft(const terrain::HeightField& f) {
  std::vector<blockers::Sphere> s;
  const glm::dvec3 a(30 * 4.0, -28 * 4.0, f.at(30, 28) + 40.0);
  for (int k = 0; k < 12; ++k) s.push_back({a + glm::dvec3(0, (k - 5.5) * 1.4, 0), 0.9});
  for (int k = 0; k < 6; ++k) s.push_back({a + glm::dvec3((k - 2.5) * 1.8, 0, 0), 1.2});
  const glm::dvec3 b(50 * 4.0, -40 * 4.0, f.at(50, 40) + 25.0);
  for (int k = 0; k < 8; ++k) s.push_back({b + glm::dvec3(3.0 * k, 1.0 * k, 0.5 * k), 4.0});
  return s;
}

ProductBands render(shading::Renderer& r, const terrain::HeightField& f, Product p, const ProductOptions& o,
                    const std::vector<blockers::Sphere>& spheres, std::optional<shading::Lighting> l) {
  r.set_field(f);
  r.set_options(o);
  return r.frame(p, {std::move(l), spheres, std::nullopt});
}

struct Compared {
  double max = 0.0, fraction_within = 0.0;
  double change_rms = 0.0, change_error_rms = 0.0;  // over the texels the spheres change
  int changed = 0;
};

// GPU against reference (with spheres), and the GPU's change against the reference's.
Compared compare(const ProductBands& gpu, const ProductBands& cpu, const ProductBands& gpu_bare,
                 const ProductBands& cpu_bare, double tol, double change_floor) {
  Compared c;
  int within = 0, valid = 0;
  double change2 = 0.0, error2 = 0.0;
  for (std::size_t t = 0; t < cpu.data.size(); ++t) {
    if (std::isnan(cpu.data[t])) {
      EXPECT_TRUE(std::isnan(gpu.data[t])) << t;
      continue;
    }
    EXPECT_TRUE(std::isfinite(gpu.data[t])) << t;
    const double d = std::abs(gpu.data[t] - cpu.data[t]);
    c.max = std::max(c.max, d);
    within += d <= tol ? 1 : 0;
    ++valid;
    const double change = cpu.data[t] - cpu_bare.data[t];
    if (std::abs(change) <= change_floor) continue;
    const double gpu_change = gpu.data[t] - gpu_bare.data[t];
    change2 += change * change;
    error2 += (gpu_change - change) * (gpu_change - change);
    ++c.changed;
  }
  c.fraction_within = valid ? static_cast<double>(within) / valid : 0.0;
  c.change_rms = c.changed ? std::sqrt(change2 / c.changed) : 0.0;
  c.change_error_rms = c.changed ? std::sqrt(error2 / c.changed) : 0.0;
  return c;
}

struct Case {
  const char* name;
  Product product;
  shading::ShadingMode mode;
  bool lit;
  double tol, max_tol, change_floor;
};

TEST_F(GpuBlockers, MatchTheReferenceInEveryBlockedProduct) {
  const terrain::HeightField f = hills();
  const std::vector<blockers::Sphere> spheres = aircraft(f);
  const shading::Lighting sun = sun_at(200.0, 35.0);
  using shading::ShadingMode;
  namespace tol = tolerance;
  const Case cases[] = {
      {"skyview", Product::Skyview, ShadingMode::SkyBrdfTable, false, tol::kSkyviewTol, tol::kSkyviewTol, 1e-4},
      {"shaded table", Product::Shaded, ShadingMode::SkyBrdfTable, false, tol::kShadedTolCodes, tol::kShadedMaxCodes, 1.5},
      {"shaded triple", Product::Shaded, ShadingMode::TripleProduct, false, tol::kShadedTolCodes, tol::kShadedMaxCodes, 1.5},
      {"shaded log-brdf", Product::Shaded, ShadingMode::LogBrdf, false, tol::kShadedTolCodes, tol::kShadedMaxCodes, 1.5},
      {"shaded lit", Product::Shaded, ShadingMode::SkyBrdfTable, true, tol::kShadedTolCodes, tol::kShadedMaxCodes, 1.5},
      {"shadow", Product::Shadow, ShadingMode::SkyBrdfTable, true, 0.02, 0.25, 0.01},
  };
  GpuRenderer gpu;
  for (const Case& k : cases) {
    ProductOptions o;
    o.threads = 2;
    o.shaded.mode = k.mode;
    std::optional<shading::Lighting> l;
    if (k.lit) l = sun;
    shading::ReferenceRenderer cpu;
    const ProductBands g = render(gpu, f, k.product, o, spheres, l), c = render(cpu, f, k.product, o, spheres, l);
    const ProductBands g0 = render(gpu, f, k.product, o, {}, l), c0 = render(cpu, f, k.product, o, {}, l);
    const Compared r = compare(g, c, g0, c0, k.tol, k.change_floor);
    std::printf("%-16s max %.4g, within %.4f, %d texels changed (RMS %.4g), change error RMS %.4g\n", k.name, r.max,
                r.fraction_within, r.changed, r.change_rms, r.change_error_rms);
    EXPECT_LE(r.max, k.max_tol) << k.name;
    EXPECT_GE(r.fraction_within, tol::kMinFraction) << k.name;
    EXPECT_GT(r.changed, 20) << k.name;  // the spheres do darken something
    EXPECT_LE(r.change_error_rms, 0.1 * r.change_rms) << k.name;
  }
}

TEST_F(GpuBlockers, IrradianceMatchesTheReferenceRelatively) {
  const terrain::HeightField f = hills();
  const std::vector<blockers::Sphere> spheres = aircraft(f);
  ProductOptions o;
  o.threads = 2;
  const shading::Lighting sun = sun_at(120.0, 20.0);
  GpuRenderer gpu;
  shading::ReferenceRenderer cpu;
  const ProductBands g = render(gpu, f, Product::Irradiance, o, spheres, sun);
  const ProductBands c = render(cpu, f, Product::Irradiance, o, spheres, sun);
  double worst = 0.0, scale = 0.0;
  for (float v : c.data) scale = std::max(scale, static_cast<double>(v));
  for (std::size_t t = 0; t < c.data.size(); ++t) worst = std::max(worst, std::abs(g.data[t] - c.data[t]) / scale);
  std::printf("irradiance: max error %.3g of the brightest texel\n", worst);
  // The sun term carries the shadow's penumbra difference (≤ 0.25 of DNI on a texel).
  EXPECT_LE(worst, 0.25);
  int close = 0;
  for (std::size_t t = 0; t < c.data.size(); ++t) close += std::abs(g.data[t] - c.data[t]) <= tolerance::kIrradianceRelTol * scale;
  EXPECT_GE(static_cast<double>(close) / c.data.size(), tolerance::kMinFraction);
}

TEST_F(GpuBlockers, TenAircraftWithMergedGroupsMatchTheReference) {
  // Ten 18-sphere aircraft 150 m over 768 m of hills at 8 m texels: far receivers take
  // each as one cap (sphere_groups.h), near ones its spheres, on both backends alike. A
  // wide merge sine (0.5: every aircraft one cap), so that merging moves the result well
  // beyond the backends' difference (at the default 0.04 it moves it by about 1e-6).
  terrain::SyntheticOptions so;
  so.width = so.height = 96;
  so.spacing = 8.0;
  so.seed = 5;
  so.relief = 60.0;
  so.feature_size = 400.0;
  const terrain::HeightField f = terrain::make_synthetic_terrain(so);
  std::vector<blockers::Sphere> s;
  for (int k = 0; k < 10; ++k) {
    const int i = 10 + 8 * k, j = 20 + 6 * (k % 5);
    const glm::dvec3 c(i * 8.0, -j * 8.0, f.at(i, j) + 150.0);
    for (int w = 0; w < 12; ++w) s.push_back({c + glm::dvec3(0, (w - 5.5) * 2.8, 0), 1.0});
    for (int b = 0; b < 6; ++b) s.push_back({c + glm::dvec3((b - 2.5) * 5.0, 0, 0), 1.5});
  }
  ProductOptions o;
  o.threads = 2;
  o.blockers.merge_sin = 0.5;
  GpuRenderer gpu;
  shading::ReferenceRenderer cpu;
  const ProductBands g = render(gpu, f, Product::Skyview, o, s, std::nullopt);
  const ProductBands c = render(cpu, f, Product::Skyview, o, s, std::nullopt);
  const ProductBands c0 = render(cpu, f, Product::Skyview, o, {}, std::nullopt);
  double worst = 0.0, change = 0.0;
  for (std::size_t t = 0; t < c.data.size(); ++t) {
    worst = std::max(worst, std::abs(static_cast<double>(g.data[t]) - c.data[t]));
    change = std::max(change, std::abs(static_cast<double>(c.data[t]) - c0.data[t]));
  }
  std::printf("ten aircraft skyview: max |gpu - reference| %.3g (largest change %.3g)\n", worst, change);
  EXPECT_GT(change, 2e-3);
  // The merge angle is baked into the kernel: the same renderer with every sphere alone
  // must match the reference's every sphere alone, not reuse the merging kernel.
  o.blockers.merge_sin = 0.0;
  const ProductBands g_alone = render(gpu, f, Product::Skyview, o, s, std::nullopt);
  const ProductBands c_alone = render(cpu, f, Product::Skyview, o, s, std::nullopt);
  double worst_alone = 0.0, moved = 0.0;
  for (std::size_t t = 0; t < c.data.size(); ++t) {
    worst_alone = std::max(worst_alone, std::abs(static_cast<double>(g_alone.data[t]) - c_alone.data[t]));
    moved = std::max(moved, std::abs(static_cast<double>(c_alone.data[t]) - c.data[t]));
  }
  std::printf("every sphere alone: max |gpu - reference| %.3g (merging moved the reference by %.3g)\n", worst_alone,
              moved);
  EXPECT_GT(moved, 5 * worst);  // the comparison below can tell merged from alone
  EXPECT_LE(worst_alone, 2 * worst + 1e-6);
  EXPECT_LE(worst, tolerance::kSkyviewTol);
}

TEST_F(GpuBlockers, HardCasesStayFinite) {
  // Spheres through the ground, 400 coincident ones, a 1 mm one and one 10 km up: finite
  // everywhere, and as the reference within the skyview tolerance where it is.
  const terrain::HeightField f = hills();
  std::vector<blockers::Sphere> s;
  const glm::dvec3 c(20 * 4.0, -20 * 4.0, f.at(20, 20));
  s.push_back({c, 6.0});                                           // centred on the ground
  for (int k = 0; k < 400; ++k) s.push_back({c + glm::dvec3(40, -40, 20), 3.0});  // coincident
  s.push_back({c + glm::dvec3(10, 0, 5), 0.001});
  s.push_back({c + glm::dvec3(0, 0, 10000), 20.0});
  ProductOptions o;
  o.threads = 2;
  GpuRenderer gpu;
  shading::ReferenceRenderer cpu;
  for (Product p : {Product::Skyview, Product::Shaded, Product::Shadow}) {
    std::optional<shading::Lighting> l;
    if (p == Product::Shadow) l = sun_at(200.0, 35.0);
    const ProductBands g = render(gpu, f, p, o, s, l), r = render(cpu, f, p, o, s, l);
    double worst = 0.0;
    for (std::size_t t = 0; t < g.data.size(); ++t) {
      ASSERT_TRUE(std::isfinite(g.data[t])) << shading::product_name(p) << " " << t;
      worst = std::max(worst, std::abs(static_cast<double>(g.data[t]) - r.data[t]));
    }
    std::printf("%s: max |gpu - reference| %.3g\n", std::string(shading::product_name(p)).c_str(), worst);
    EXPECT_LE(worst, p == Product::Shaded ? tolerance::kShadedMaxCodes + 1.0 : 0.05) << shading::product_name(p);
  }
}

TEST_F(GpuBlockers, UnsupportedOptionsFallBackWithAReason) {
  ProductOptions o;
  o.blockers.blocker.log = blockers::CapLog::kPointwise;
  GpuRenderer gpu;
  const auto why = gpu.lacks_blockers(Product::Skyview, o);
  ASSERT_TRUE(why.has_value());
  EXPECT_NE(why->find("log"), std::string::npos);
  EXPECT_FALSE(gpu.lacks_blockers(Product::Skyview, ProductOptions{}).has_value());
  EXPECT_FALSE(gpu.lacks_blockers(Product::Svf, o).has_value());  // svf is never blocked
}

}  // namespace
}  // namespace skylit::gpu
