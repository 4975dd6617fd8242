// The viewer's sky model kept while the sun moves little (view/lighting_reuse.h): which frames
// keep it, and what keeping it costs against the sky of the frame's own sun, measured on
// the GPU renderer's irradiance (itself matched to the CPU reference by gpu_lighting_test).
#include "gpu_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <cstdio>
#include <numbers>

#include "gpu/gpu_pipeline.h"
#include "shading/lighting.h"
#include "shading/sun_light.h"
#include "view/scene_view.h"
#include "view/lighting_reuse.h"

namespace skylit::view {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

shading::LightingRequest request_at(double azimuth_deg, double elevation_deg, double turbidity = 3.0) {
  shading::LightingRequest r;
  r.sun_azimuth_deg = azimuth_deg;
  r.sun_elevation_deg = elevation_deg;
  r.sky = "preetham";
  r.turbidity = turbidity;
  return r;
}
shading::Lighting resolve(const shading::LightingRequest& r) { return shading::resolve_lighting(r, std::nullopt).lighting; }

// An azimuth step that moves a sun at `elevation_deg` by `angle_deg` on the sky.
double azimuth_step(double angle_deg, double elevation_deg) { return angle_deg / std::cos(elevation_deg * kDeg); }

TEST(LightingReuse, KeepsTheLightingWhileTheSunStaysWithinTheAngleAndTheModelWhileItStaysNearWhereItWasMade) {
  LightingReuse reuse(kSunTolerance, kSkyTolerance);
  const double tol_deg = kSunTolerance / kDeg, sky_deg = kSkyTolerance / kDeg;
  ASSERT_GT(sky_deg, 2.0 * tol_deg) << "the case's premise";
  const shading::Lighting first = reuse.next(request_at(140, 30), resolve(request_at(140, 30)));
  auto next = [&](double azimuth, double elevation = 30, double turbidity = 3.0) {
    const shading::LightingRequest r = request_at(azimuth, elevation, turbidity);
    return reuse.next(r, resolve(r));
  };
  auto same = [](const shading::Lighting& a, const shading::Lighting& b) {
    return a.sky == b.sky && a.sun.direction == b.sun.direction && a.sun.dni == b.sun.dni &&
           a.reference_irradiance == b.reference_irradiance;
  };
  // Within the angle of the last lighting, at mid-day's slowly changing DNI: all kept.
  EXPECT_TRUE(same(next(140 + azimuth_step(0.5 * tol_deg, 30)), first));
  EXPECT_TRUE(same(next(140 + azimuth_step(0.99 * tol_deg, 30)), first));
  // Beyond the lighting's angle but within the sky's: the frame's own sun under the kept model.
  const shading::Lighting fresh = resolve(request_at(140 + azimuth_step(1.01 * tol_deg, 30), 30));
  const shading::Lighting second = next(140 + azimuth_step(1.01 * tol_deg, 30));
  EXPECT_EQ(second.sky, first.sky);
  EXPECT_EQ(second.sun.direction, fresh.sun.direction);
  EXPECT_TRUE(same(next(140 + azimuth_step(1.5 * tol_deg, 30)), second));
  // Beyond the sky's angle from where the model was made: all the frame's own.
  const shading::Lighting far = resolve(request_at(140 + azimuth_step(1.01 * sky_deg, 30), 30));
  const shading::Lighting third = next(140 + azimuth_step(1.01 * sky_deg, 30));
  EXPECT_NE(third.sky, first.sky);
  EXPECT_EQ(third.sun.direction, far.sun.direction);
  EXPECT_TRUE(same(next(140 + azimuth_step(1.01 * sky_deg + 0.5 * tol_deg, 30)), third));
  EXPECT_NE(next(140 + azimuth_step(1.01 * sky_deg, 30), 30, 4.0).sky, third.sky) << "another turbidity";

  // A low sun: a step well within the angle changes the DNI by more than the relative
  // tolerance, so the frame gets its own sun under the kept sky model.
  const shading::Lighting low = next(140, 1.5);
  const shading::Lighting risen = resolve(request_at(140, 1.5 + 0.9 * tol_deg));
  ASSERT_GT(std::abs(risen.sun.dni.g / low.sun.dni.g - 1.0), kLightingRelativeTolerance) << "the case's premise";
  const shading::Lighting out = next(140, 1.5 + 0.9 * tol_deg);
  EXPECT_EQ(out.sky, low.sky) << "the model kept";
  EXPECT_EQ(out.sun.direction, risen.sun.direction) << "the sun the frame's own";
  EXPECT_EQ(out.sun.dni, risen.sun.dni);

  // The time is not part of what must match; everything else is.
  shading::LightingRequest timed = request_at(200, 20);
  timed.time = "2026-06-21T10:00:00Z";
  const shading::Lighting t0 = reuse.next(timed, resolve(request_at(200, 20)));
  timed.time = "2026-06-21T10:00:01Z";
  EXPECT_TRUE(same(reuse.next(timed, resolve(request_at(200, 20))), t0));
  EXPECT_THROW(LightingReuse(-1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(LightingReuse(kSunTolerance, 0.5 * kSunTolerance), std::invalid_argument);
}

using ViewLightingReuseTest = gpu::testing::GpuTest;

// The irradiance under `own` and under `kept` (the same lighting shape), per valid texel.
struct IrradianceChange {
  double brightest = 0.0;  // under `own`
  double worst = 0.0, mean = 0.0;
  std::size_t texels = 0, over = 0;  // valid texels, and those changed by more than `bound`
};
IrradianceChange irradiance_change(const terrain::HeightField& f, const shading::Lighting& own,
                                   const shading::Lighting& kept, double bound_over_brightest = 0.0,
                                   double bound = std::numeric_limits<double>::infinity()) {
  shading::ProductOptions o;
  o.lighting = own;
  gpu::GpuProductPipeline p(shading::Product::Irradiance, o);
  const std::vector<float> a = p.compute(f).data;
  p.set_lighting(kept);
  const std::vector<float> b = p.compute(f).data;
  IrradianceChange c;
  for (float v : a)
    if (!std::isnan(v)) c.brightest = std::max(c.brightest, static_cast<double>(v));
  bound += bound_over_brightest * c.brightest;
  for (std::size_t q = 0; q < a.size(); ++q) {
    if (std::isnan(a[q])) continue;
    const double e = std::abs(static_cast<double>(a[q]) - b[q]);
    c.worst = std::max(c.worst, e);
    c.mean += e;
    c.over += e > bound ? 1 : 0;
    ++c.texels;
  }
  c.mean /= static_cast<double>(c.texels);
  return c;
}

// The sky made for a sun kSkyTolerance away, against the frame's own: the irradiance
// changes by less than 1e-3 of the frame's brightest texel, at a middle and a low sun.
TEST_F(ViewLightingReuseTest, AKeptSkyChangesTheIrradianceByLessThanAThousandth) {
  const terrain::HeightField f = gpu::testing::synthetic_field({128, 112});
  for (double elevation : {30.0, 6.0}) {
    const double a0 = 140.0, a1 = a0 + azimuth_step(0.999 * kSkyTolerance / kDeg, elevation);
    shading::Lighting own = resolve(request_at(a1, elevation)), kept = own;
    kept.sky = resolve(request_at(a0, elevation)).sky;
    const IrradianceChange c = irradiance_change(f, own, kept);
    std::printf("sun at %.0f deg: kept sky against its own, mean %.3g, max %.3g W/m2 of %.4g\n", elevation, c.mean,
                c.worst, c.brightest);
    EXPECT_GT(c.worst, 0.0) << "the sky did change";
    EXPECT_LT(c.worst, 1e-3 * c.brightest) << elevation;
  }
}

// The whole lighting of a sun kSunTolerance (δ) away, under a sky model made for a sun
// kSkyTolerance away, against the frame's own. Under a fixed horizon a texel's irradiance
// moves by at most DNI·(4δ/(π r) + δ) + |ΔDNI| + the kept sky's change: the disc (radius
// r) shifted by δ leaves at most 4rδ of its area πr² on another side of the horizon and
// tangent-plane lines, n·s moves by at most δ, and the sky model is the previous test's
// (under 1e-3 of the brightest texel). The horizon along
// the sun's heading also moves with it, by a whole ridge where the ray grazes one (as it
// does for the far slopes kept at the same angle, gpu_frame_reuse_test): few texels may
// pass the bound (measured 0.03 % at 30°, 0.13 % at 6°; at most 0.5 %), and the mean
// stays under DNI·δ (n·s) and a thousandth of the brightest texel (the sky): 0.99 W/m²
// at 30° against 1.58.
TEST_F(ViewLightingReuseTest, AKeptLightingMovesEachTexelWithinTheDiscBound) {
  const terrain::HeightField f = gpu::testing::synthetic_field({128, 112});
  const double delta = 0.999 * kSunTolerance, r = shading::SunShadowOptions{}.radius;
  for (double elevation : {30.0, 6.0}) {
    const double a0 = 140.0, a1 = a0 + azimuth_step(delta / kDeg, elevation);
    const shading::Lighting own = resolve(request_at(a1, elevation));
    shading::Lighting kept = resolve(request_at(a0, elevation));
    kept.sky = resolve(request_at(a1 - azimuth_step(0.999 * kSkyTolerance / kDeg, elevation), elevation)).sky;
    const double bound = own.sun.dni.g * (4.0 * delta / (std::numbers::pi * r) + delta) +
                         std::abs(own.sun.dni.g - kept.sun.dni.g);
    const IrradianceChange c = irradiance_change(f, own, kept, 1e-3, bound);
    const double mean_bound = own.sun.dni.g * delta + 1e-3 * c.brightest;
    std::printf("sun at %.0f deg: kept lighting against its own, mean %.3g (bound %.3g), max %.3g W/m2 of %.4g; %zu of "
                "%zu texels over the fixed-horizon bound\n",
                elevation, c.mean, mean_bound, c.worst, c.brightest, c.over, c.texels);
    EXPECT_GT(c.worst, 0.0) << "the lighting did change";
    EXPECT_LE(c.over, c.texels / 200) << elevation;
    EXPECT_LT(c.mean, mean_bound) << elevation;
  }
}

}  // namespace
}  // namespace skylit::view
