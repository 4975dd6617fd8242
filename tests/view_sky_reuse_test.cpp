// The viewer's sky model kept while the sun moves little (view/sky_reuse.h): which frames
// keep it, and what keeping it costs against the sky of the frame's own sun, measured on
// the GPU renderer's irradiance (itself matched to the CPU reference by gpu_lighting_test).
#include "gpu_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "gpu/gpu_pipeline.h"
#include "shading/lighting.h"
#include "view/scene_view.h"
#include "view/sky_reuse.h"

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

TEST(SkyReuse, KeepsTheModelWhileTheSunStaysWithinTheAngleOfWhereItWasMade) {
  SkyReuse reuse(kSunTolerance);
  const double tol_deg = kSunTolerance / kDeg;
  const shading::Lighting first = reuse.next(request_at(140, 30), resolve(request_at(140, 30)));
  auto next = [&](double azimuth, double turbidity = 3.0) {
    const shading::LightingRequest r = request_at(azimuth, 30, turbidity);
    const shading::Lighting fresh = resolve(r);
    const shading::Lighting out = reuse.next(r, fresh);
    EXPECT_EQ(out.sun.direction, fresh.sun.direction) << "the sun is always the frame's";
    EXPECT_EQ(out.sun.dni, fresh.sun.dni);
    return out;
  };
  EXPECT_EQ(next(140 + azimuth_step(0.5 * tol_deg, 30)).sky, first.sky);
  EXPECT_EQ(next(140 + azimuth_step(0.99 * tol_deg, 30)).sky, first.sky) << "measured from where it was made";
  const shading::Lighting second = next(140 + azimuth_step(1.01 * tol_deg, 30));
  EXPECT_NE(second.sky, first.sky);
  EXPECT_EQ(next(140 + azimuth_step(1.5 * tol_deg, 30)).sky, second.sky);
  EXPECT_NE(next(140 + azimuth_step(1.5 * tol_deg, 30), 4.0).sky, second.sky) << "another turbidity";
  // The time is not part of what must match; everything else is.
  shading::LightingRequest timed = request_at(200, 20);
  timed.time = "2026-06-21T10:00:00Z";
  const shading::Lighting t0 = reuse.next(timed, resolve(request_at(200, 20)));
  timed.time = "2026-06-21T10:00:01Z";
  EXPECT_EQ(reuse.next(timed, resolve(request_at(200, 20))).sky, t0.sky);
  EXPECT_THROW(SkyReuse(-1.0), std::invalid_argument);
}

using ViewSkyReuseTest = gpu::testing::GpuTest;

// The sky made for a sun kSunTolerance away, against the frame's own: the irradiance
// changes by less than 1e-3 of the frame's brightest texel, at a middle and a low sun.
TEST_F(ViewSkyReuseTest, AKeptSkyChangesTheIrradianceByLessThanAThousandth) {
  const terrain::HeightField f = gpu::testing::synthetic_field({128, 112});
  for (double elevation : {30.0, 6.0}) {
    const double a0 = 140.0, a1 = a0 + azimuth_step(0.999 * kSunTolerance / kDeg, elevation);
    shading::Lighting own = resolve(request_at(a1, elevation)), kept = own;
    kept.sky = resolve(request_at(a0, elevation)).sky;
    shading::ProductOptions o;
    o.lighting = own;
    gpu::GpuProductPipeline p(shading::Product::Irradiance, o);
    const std::vector<float> a = p.compute(f).data;
    p.set_lighting(kept);
    const std::vector<float> b = p.compute(f).data;
    double brightest = 0.0, worst = 0.0, mean = 0.0;
    std::size_t n = 0;
    for (std::size_t q = 0; q < a.size(); ++q) {
      if (std::isnan(a[q])) continue;
      brightest = std::max(brightest, static_cast<double>(a[q]));
      worst = std::max(worst, std::abs(static_cast<double>(a[q]) - b[q]));
      mean += std::abs(static_cast<double>(a[q]) - b[q]);
      ++n;
    }
    mean /= static_cast<double>(n);
    std::printf("sun at %.0f deg: kept sky against its own, mean %.3g, max %.3g W/m2 of %.4g\n", elevation, mean, worst,
                brightest);
    EXPECT_GT(worst, 0.0) << "the sky did change";
    EXPECT_LT(worst, 1e-3 * brightest) << elevation;
  }
}

}  // namespace
}  // namespace skylit::view
