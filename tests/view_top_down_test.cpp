// The viewer's drawing path tied to the verified export: straight down over the field,
// the frame (terrain mesh, the renderer's `shaded` frame sampled on the GPU, the
// viewer's own tone map in GLSL) equals the `shaded` raster — the GPU's read back and
// coded on the host as `skylit shade` writes it, and the CPU reference's — and an
// aircraft's shadow lands where the sun's ray through it meets the ground. llvmpipe
// where there is no GPU.
#include "lighting_test_util.h"
#include "gpu_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "gpu/gpu_renderer.h"
#include "shading/lighting.h"
#include "shading/products.h"
#include "shading/reference_renderer.h"
#include "view/offscreen_target.h"
#include "view/scene_view.h"

namespace skylit::view {
namespace {

using ::skylit::testing::sun_at;  // lighting_test_util.h

using shading::Product;

using TopDownTest = gpu::testing::GpuTest;

shading::ProductOptions options(shading::ToneCurve tone) {
  shading::ProductOptions o;
  o.march.azimuths = 16;
  o.shaded.tone = tone;
  return o;
}

// The top-down frame of the field-sized viewport, RGB, top row first, on `clear` where
// nothing is drawn.
std::vector<std::uint8_t> top_down(gpu::GpuRenderer& renderer, const terrain::HeightField& f,
                                   const shading::ProductOptions& o, const shading::FrameInputs& inputs,
                                   const glm::dvec3& clear = glm::dvec3(0.0)) {
  SceneView view(renderer, f, o, !inputs.spheres.empty());
  OffscreenTarget target(f.width, f.height);
  target.bind();
  ViewFrame frame;
  frame.shading = inputs;
  frame.camera = ortho_nadir_camera(f, 1.0);
  frame.style.tone = o.shaded.tone;
  frame.draw_bodies = false;
  frame.clear = clear;
  view.draw(frame, f.width, f.height);
  return target.read_rgb();
}

struct Difference {
  double rms = 0.0;
  int max = 0;
  int compared = 0;
};

// Frame codes against a raster's codes (bands: 1 grey or 3), valid texels only.
Difference compare(const std::vector<std::uint8_t>& rgb, const shading::ProductBands& codes) {
  Difference d;
  double sum = 0.0;
  for (int j = 0; j < codes.height; ++j)
    for (int i = 0; i < codes.width; ++i)
      for (int c = 0; c < 3; ++c) {
        const float want = codes.at(std::min(c, codes.bands - 1), i, j);
        if (std::isnan(want)) continue;
        const int got = rgb[(static_cast<std::size_t>(j) * codes.width + i) * 3 + c];
        const int diff = std::abs(got - static_cast<int>(want));
        sum += diff * diff;
        d.max = std::max(d.max, diff);
        ++d.compared;
      }
  d.rms = std::sqrt(sum / std::max(d.compared, 1));
  return d;
}

shading::ProductBands reference_codes(const terrain::HeightField& f, const shading::ProductOptions& o,
                                      const shading::FrameInputs& inputs) {
  shading::ReferenceRenderer reference;
  reference.set_field(f);
  reference.set_options(o);
  return reference.frame(Product::Shaded, inputs);
}

TEST_F(TopDownTest, UnlitShadedEqualsTheExportRaster) {
  const terrain::HeightField f = gpu::testing::synthetic_field();
  const shading::ProductOptions o = options(shading::ToneCurve::Linear);
  gpu::GpuRenderer renderer;
  const shading::FrameInputs inputs;
  const std::vector<std::uint8_t> rgb = top_down(renderer, f, o, inputs);
  renderer.set_field(f);
  const shading::ProductBands codes = renderer.frame(Product::Shaded, inputs);
  const Difference vs_gpu = compare(rgb, codes);
  EXPECT_GT(vs_gpu.compared, f.width * f.height * 3 - 10);
  EXPECT_LE(vs_gpu.max, 1) << "the same values, coded in GLSL instead of on the host";
  EXPECT_LT(vs_gpu.rms, 0.1);
  const Difference vs_reference = compare(rgb, reference_codes(f, o, inputs));
  EXPECT_LT(vs_reference.rms, 2.0);
}

TEST_F(TopDownTest, LitColourShadedWithAnAircraftEqualsTheExportRaster) {
  const terrain::HeightField f = gpu::testing::synthetic_field();
  const shading::ProductOptions o = options(shading::ToneCurve::Srgb);
  gpu::GpuRenderer renderer;
  shading::FrameInputs inputs;
  inputs.lighting = sun_at(135.0, 30.0, "preetham");
  inputs.spheres = {{{45 * 30.0, -40 * 30.0, 2400.0}, 60.0}};
  const std::vector<std::uint8_t> rgb = top_down(renderer, f, o, inputs);
  renderer.set_field(f);
  const shading::ProductBands gpu_codes = renderer.frame(Product::Shaded, inputs);
  ASSERT_EQ(gpu_codes.bands, 3);
  const Difference vs_gpu = compare(rgb, gpu_codes);
  EXPECT_LE(vs_gpu.max, 1);
  EXPECT_LT(vs_gpu.rms, 0.1);
  const Difference vs_reference = compare(rgb, reference_codes(f, o, inputs));
  EXPECT_LT(vs_reference.rms, 2.0);
}

TEST_F(TopDownTest, NodataIsLeftUndrawnAndTakesNoColourIntoTheGround) {
  // A 12 × 8 hole of nodata, filled with a cliff the renderer must not show: its texels
  // keep the clear colour, and every valid texel, the hole's rim included, equals the
  // export's codes (the colour map gives nodata a valid neighbour's colour).
  terrain::HeightField f = gpu::testing::synthetic_field();
  for (int j = 30; j < 38; ++j)
    for (int i = 20; i < 32; ++i) {
      f.valid[static_cast<std::size_t>(j) * f.width + i] = 0;
      f.heights[static_cast<std::size_t>(j) * f.width + i] = 5000.0f;
    }
  const shading::ProductOptions o = options(shading::ToneCurve::Linear);
  gpu::GpuRenderer renderer;
  const shading::FrameInputs inputs;
  const std::vector<std::uint8_t> rgb = top_down(renderer, f, o, inputs, {1.0, 0.0, 1.0});
  renderer.set_field(f);
  const shading::ProductBands codes = renderer.frame(Product::Shaded, inputs);
  int hole = 0, magenta = 0;
  for (int j = 0; j < f.height; ++j)
    for (int i = 0; i < f.width; ++i) {
      if (f.is_valid(i, j)) continue;
      ++hole;
      const std::size_t p = (static_cast<std::size_t>(j) * f.width + i) * 3;
      magenta += rgb[p] == 255 && rgb[p + 1] == 0 && rgb[p + 2] == 255;
    }
  EXPECT_GE(hole, 96);  // the hole, and the scene's own nodata
  EXPECT_EQ(magenta, hole);
  const Difference d = compare(rgb, codes);  // valid texels only (the codes are NaN on nodata)
  EXPECT_GT(d.compared, (f.width * f.height - hole) * 3 - 10);
  EXPECT_LE(d.max, 1);
  EXPECT_LT(d.rms, 0.1);
}

TEST_F(TopDownTest, AircraftShadowLandsWhereTheSunRayMeetsTheGround) {
  // Flat ground at 0 m, one 40 m sphere 300 m up; sun from azimuth 120°, elevation 35°.
  terrain::HeightField f(160, 160, 10.0);
  const double azimuth = 120.0, elevation = 35.0, height = 300.0;
  const glm::dvec3 centre{80 * 10.0, -80 * 10.0, height};
  shading::FrameInputs lit;
  lit.lighting = sun_at(azimuth, elevation, "uniform");
  shading::FrameInputs blocked = lit;
  blocked.spheres = {{centre, 40.0}};
  gpu::GpuRenderer renderer;
  const shading::ProductOptions o = options(shading::ToneCurve::Linear);
  const std::vector<std::uint8_t> clear = top_down(renderer, f, o, lit);
  const std::vector<std::uint8_t> shadowed = top_down(renderer, f, o, blocked);

  // The ground point behind the sphere, away from the sun: centre − h / tan(e) · (sin A, cos A).
  const double a = azimuth * std::numbers::pi / 180.0, e = elevation * std::numbers::pi / 180.0;
  const double run = height / std::tan(e);
  const double want_x = centre.x - run * std::sin(a), want_y = centre.y - run * std::cos(a);
  double weight = 0.0, sx = 0.0, sy = 0.0;
  int darkest = 0;
  for (int j = 0; j < f.height; ++j)
    for (int i = 0; i < f.width; ++i) {
      const std::size_t p = (static_cast<std::size_t>(j) * f.width + i) * 3;
      const int dark = clear[p] - shadowed[p];
      darkest = std::max(darkest, dark);
      if (dark <= 0) continue;
      weight += dark;
      sx += dark * i * 10.0;
      sy += dark * -j * 10.0;
    }
  ASSERT_GT(darkest, 40) << "a 40 m sphere's umbra takes most of the direct sun";
  EXPECT_NEAR(sx / weight, want_x, 15.0);
  EXPECT_NEAR(sy / weight, want_y, 15.0);
}

// Frames seen from `eye` looking north over `f`, the sun behind the eye under a uniform
// sky, without and with a sphere at `centre` (RGB, top row first).
struct WithoutAndWith {
  std::vector<std::uint8_t> without, with;
};
WithoutAndWith looking_north(const terrain::HeightField& f, const glm::dvec3& eye, const blockers::Sphere& sphere,
                             int size, bool curvature = true) {
  shading::FrameInputs without;
  without.lighting = sun_at(180.0, 35.0, "uniform");
  shading::FrameInputs with = without;
  with.spheres = {sphere};
  gpu::GpuRenderer renderer;
  const shading::ProductOptions o = options(shading::ToneCurve::Linear);
  SceneView view(renderer, f, o, true);  // the frame without the sphere takes the same kernels
  OffscreenTarget target(size, size);
  auto draw = [&](const shading::FrameInputs& inputs) {
    target.bind();
    ViewFrame frame;
    frame.shading = inputs;
    frame.camera = perspective_camera({eye, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}}, f, size, size, 1.0, inputs.spheres);
    frame.style.tone = o.shaded.tone;
    frame.style.curvature = curvature;
    view.draw(frame, size, size);
    return target.read_rgb();
  };
  WithoutAndWith out;
  out.without = draw(without);
  out.with = draw(with);
  return out;
}

TEST_F(TopDownTest, AircraftIsDrawnWherePerspectivePutsIt) {
  // Flat ground at 0 m; the eye looking north at a 20 m sphere ahead at the eye's height,
  // the sun behind the eye: on screen a disc at the centre whose radius is
  // ppr · tan(asin(r/d)) pixels. 1000 m up with the sphere 120 m ahead, a near plane
  // from the height alone (500 m) would clip it away.
  terrain::HeightField f(160, 160, 10.0);
  for (const auto& [height, ahead] : {std::pair{150.0, 500.0}, std::pair{1000.0, 120.0}}) {
    const glm::dvec3 eye{800.0, -1300.0, height}, centre{800.0, -1300.0 + ahead, height};
    const double r = 20.0;
    const int size = 256;
    const auto [bare, drawn] = looking_north(f, eye, {centre, r}, size);
    const double ppr = size / (2.0 * std::tan(25.0 * std::numbers::pi / 180.0));
    const double radius_px = ppr * std::tan(std::asin(r / glm::distance(eye, centre)));
    int inside = 0, inside_changed = 0, outside_changed = 0;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const double dx = x + 0.5 - 0.5 * size, dy = y + 0.5 - 0.5 * size;  // y down (top row first)
        if (dy > 30.0) continue;  // below: the sphere's shadow on the ground, 214 m behind it
        const std::size_t p = (static_cast<std::size_t>(y) * size + x) * 3;
        const bool changed = bare[p] != drawn[p] || bare[p + 1] != drawn[p + 1] || bare[p + 2] != drawn[p + 2];
        const double rho = std::hypot(dx, dy);
        if (rho < radius_px - 1.5) {
          ++inside;
          inside_changed += changed;
        } else if (rho > radius_px + 1.5) {
          outside_changed += changed;
        }
      }
    EXPECT_GT(radius_px, 10.0);
    // A few rim pixels may match the haze behind by chance.
    EXPECT_GT(inside_changed, 0.98 * inside) << "the sphere covers its disc; eye " << height << " m, " << ahead << " m";
    EXPECT_EQ(outside_changed, 0) << "and nothing else above its shadow; eye " << height << " m";
  }
}

TEST_F(TopDownTest, AFarAircraftFallsWithTheCurvedGround) {
  // The ground is drawn d^2 / (2R) lower at distance d from the eye; an aircraft 25 km
  // ahead at the eye's height falls with it, 49 m: ppr · 49 / 25000 ≈ 2.2 px below the
  // screen's centre at 1024 px, and on the centre with the curvature off.
  terrain::HeightField f(160, 160, 200.0);  // flat, 32 km square
  const double ahead = 25000.0, r = 150.0;
  const glm::dvec3 eye{16000.0, -31000.0, 1000.0}, centre{16000.0, -31000.0 + ahead, 1000.0};
  const int size = 1024;
  const double ppr = size / (2.0 * std::tan(25.0 * std::numbers::pi / 180.0));
  for (const bool curvature : {true, false}) {
    const auto [bare, drawn] = looking_north(f, eye, {centre, r}, size, curvature);
    double n = 0.0, sx = 0.0, sy = 0.0;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const double dx = x + 0.5 - 0.5 * size, dy = y + 0.5 - 0.5 * size;  // y down (top row first)
        if (std::abs(dx) > 20.0 || std::abs(dy) > 20.0) continue;  // the shadow is 40 px below
        const std::size_t p = (static_cast<std::size_t>(y) * size + x) * 3;
        if (bare[p] == drawn[p] && bare[p + 1] == drawn[p + 1] && bare[p + 2] == drawn[p + 2]) continue;
        n += 1.0;
        sx += dx;
        sy += dy;
      }
    const double earth_radius_m = 6371000.0;
    const double want_px = curvature ? ppr * (ahead * ahead * 0.5 / earth_radius_m) / ahead : 0.0;
    const double radius_px = ppr * r / ahead;
    ASSERT_GT(n, 0.8 * std::numbers::pi * radius_px * radius_px) << "curvature " << curvature;
    EXPECT_NEAR(sx / n, 0.0, 0.3) << "curvature " << curvature;
    EXPECT_NEAR(sy / n, want_px, 0.3) << "curvature " << curvature;
  }
}

}  // namespace
}  // namespace skylit::view
