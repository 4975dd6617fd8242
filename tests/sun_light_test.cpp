// Sun shadow fraction per texel (sun_light.h) on analytic scenes against closed forms
// derived here (no marching), the three horizon sources against each other, and the
// sun's irradiance.
#include "horizon_scenes.h"

#include "shading/horizon/horizon_sweep.h"
#include "shading/horizon/surface_normals.h"
#include "shading/sky/sun_disc.h"
#include "shading/sun_light.h"
#include "terrain/synthetic.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

namespace skylit::shading {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;
const double kR = sky::kSunAngularRadius;

SunShadowOptions flat_earth(SunHorizon h) {
  SunShadowOptions o;
  o.horizon = h;
  o.march.curvature.enabled = false;
  o.exact.curvature.enabled = false;
  return o;
}

const SunHorizon kAll[] = {SunHorizon::Marched, SunHorizon::Interpolated, SunHorizon::Exact};

float at(const std::vector<float>& v, const terrain::HeightField& f, int i, int j) {
  return v[static_cast<std::size_t>(j) * f.width + i];
}

TEST(SunShadow, FlatGroundLitShadowedAndHalfAtTheHorizon) {
  const auto f = test::make_field(24, 24, 10.0);
  for (SunHorizon h : kAll) {
    const auto o = flat_earth(h);
    for (float v : shadow_fraction_field(f, {1.0, 10 * kDeg}, o)) EXPECT_FLOAT_EQ(v, 1.0f);
    for (float v : shadow_fraction_field(f, {1.0, -1 * kDeg}, o)) EXPECT_FLOAT_EQ(v, 0.0f);
    // Sun centred on the horizontal: the tangent plane and the flat horizon halve it.
    for (float v : shadow_fraction_field(f, {4.0, 0.0}, o)) EXPECT_NEAR(v, 0.5f, 1e-6);
  }
}

TEST(SunShadow, TiltedPlaneTerminatorIsTheClosedFormPenumbra) {
  // Plane rising east with slope s: seen toward azimuth A its elevation is
  // atan(tan s·sin A), and the sun's centre lies asin(n·ŝ) from the tangent plane
  // (a great circle, a straight line across the disc): fraction = 1 − segment(u).
  const double s = 20 * kDeg;
  const auto f = test::tilted_plane(48, 10.0, s);
  const glm::dvec3 n{-std::sin(s), 0.0, std::cos(s)};
  for (double az : {90 * kDeg, 60 * kDeg})
    for (double du : {-0.7, -0.2, 0.0, 0.4, 0.9}) {
      const double plane = std::atan(std::tan(s) * std::sin(az));
      const SunAngles sun{az, plane + du * kR / 1.0};
      const double expected = sky::disc_fraction_above_line(std::asin(glm::dot(n, sun_direction(sun))) / kR);
      for (int variant = 0; variant < 4; ++variant) {
        const SunHorizon h = variant < 3 ? kAll[variant] : SunHorizon::Marched;
        auto o = flat_earth(h);
        o.disc_slope = variant == 0;
        o.march.azimuths = 360;  // Interpolated: bands 1° apart, interpolation error ≈ 0.002 r
        const auto v = shadow_fraction_field(f, sun, o);
        // Marched at A_s only puts a level line where the plane's horizon tilts by
        // dσ/dA ≈ 0.18 at 60°: a few percent of the disc.
        const double tol = variant == 3 ? 0.03 : h == SunHorizon::Interpolated ? 3e-3 : 1e-3;
        for (int j = 20; j < 28; ++j)
          for (int i = 4; i < 12; ++i)
            ASSERT_NEAR(at(v, f, i, j), expected, tol) << static_cast<int>(h) << " az " << az << " du " << du;
      }
    }
}

TEST(SunShadow, PlaneFacingAwayIsBehindItsTangentPlaneAndFacingTheSunIsLit) {
  const double s = 25 * kDeg;
  const auto f = test::tilted_plane(32, 10.0, s);
  for (SunHorizon h : kAll) {
    const auto behind = shadow_fraction_field(f, {90 * kDeg, 15 * kDeg}, flat_earth(h));
    const auto facing = shadow_fraction_field(f, {270 * kDeg, 5 * kDeg}, flat_earth(h));
    for (int j = 1; j < 31; ++j)
      for (int i = 1; i < 31; ++i) {
        EXPECT_FLOAT_EQ(at(behind, f, i, j), 0.0f);
        EXPECT_FLOAT_EQ(at(facing, f, i, j), 1.0f);
      }
  }
}

TEST(SunShadow, WallShadowEdgeMatchesClosedFormAtAnyAzimuth) {
  // test::wall: a receiver D east of the face sees it at σ(ψ) = atan(a·cos ψ), a = H/D,
  // ψ = A − 270°, so dσ/dA = −a·sin ψ/(1 + a²cos²ψ): a line across the disc whose
  // visible fraction is sun_disc_fraction(e, σ, dσ/dA) up to the O(r) curvature of σ.
  const int n = 61, c = n / 2;
  const double dx = 10.0, height = 100.0;
  const auto f = test::wall(n, dx, 5, 3, 25, height);  // face top at column 7
  const int i = 47;
  const double a = height / ((i - 7) * dx);
  for (double psi : {0.0, 25 * kDeg}) {
    const double sigma = std::atan(a * std::cos(psi));
    const double slope = -a * std::sin(psi) / (1.0 + a * a * std::cos(psi) * std::cos(psi));
    for (double du : {-0.6, -0.2, 0.3, 0.8}) {
      const SunAngles sun{270 * kDeg + psi, sigma + du * kR};
      const double expected = sky::sun_disc_fraction(sun.elevation, sigma, slope);
      EXPECT_GT(expected, 0.02);
      EXPECT_LT(expected, 0.98);
      const auto v = shadow_fraction_field(f, sun, flat_earth(SunHorizon::Exact));
      EXPECT_NEAR(at(v, f, i, c), expected, 2e-3) << psi << " " << du;
    }
  }
}

TEST(SunShadow, MarchedAndInterpolatedApproachTheExactHorizonOnRoughTerrain) {
  terrain::SyntheticOptions so;
  so.width = so.height = 72;
  so.spacing = 30.0;
  so.feature_size = 1500.0;
  so.relief = 600.0;
  const auto f = terrain::make_synthetic_terrain(so);
  const SunAngles sun{(200 + 0.37) * kDeg, 8 * kDeg};
  const auto truth = shadow_fraction_field(f, sun, flat_earth(SunHorizon::Exact));
  auto mean_abs = [&](const std::vector<float>& v) {
    double sum = 0.0;
    for (std::size_t k = 0; k < v.size(); ++k) sum += std::abs(v[k] - truth[k]);
    return sum / v.size();
  };
  double shaded = 0.0;
  for (float t : truth) shaded += t < 0.5f;
  EXPECT_GT(shaded / truth.size(), 0.1);  // the scene does cast shadows
  // The sun's own march (level 0, k_v = 32) vs the sky's pyramid march, which lowers
  // ridges and lights texels that are in shadow.
  const double e_marched = mean_abs(shadow_fraction_field(f, sun, flat_earth(SunHorizon::Marched)));
  auto sky = flat_earth(SunHorizon::Marched);
  sky.march = horizon::MarchOptions{};
  sky.march.curvature.enabled = false;
  const double e_sky = mean_abs(shadow_fraction_field(f, sun, sky));
  EXPECT_LT(e_marched, 0.02);
  EXPECT_LT(e_marched, 0.5 * e_sky);
  // Dense product azimuths (0.09° apart, finer than the disc) with the same march: the
  // interpolant sees what the marcher sees in the sun's own azimuth.
  auto dense = flat_earth(SunHorizon::Interpolated);
  dense.march.azimuths = 4096;
  EXPECT_LT(mean_abs(shadow_fraction_field(f, sun, dense)), e_marched + 0.005);
  // Coarse interpolation is worse than marching the sun's azimuth.
  auto coarse = flat_earth(SunHorizon::Interpolated);
  coarse.march.azimuths = 8;
  EXPECT_GT(mean_abs(shadow_fraction_field(f, sun, coarse)), e_marched);
  std::printf("mean |error|: sun march %.4f, sky march %.4f\n", e_marched, e_sky);
}

TEST(SunShadow, TheSweepsFloorLeavesEveryDiscFractionBitForBit) {
  // The swept sun lowers far slopes under shading::sun_sweep_floor. Against the far
  // slopes without it, every texel's disc fraction (sun_disc.h, the tangent plane and
  // the level horizon) is the same double, and shadow_fraction_field returns it.
  terrain::SyntheticOptions so;
  so.width = 120;
  so.height = 96;
  const auto f = terrain::make_synthetic_terrain(so);
  SunShadowOptions o;
  o.horizon = SunHorizon::Swept;
  EXPECT_TRUE(std::isinf(sun_sweep_floor(kSunFloorMinElevation - 0.01, o)));
  std::size_t lowered = 0, partial = 0;
  for (const double elevation_deg : {30.0, 45.0, 70.0})
    for (const double azimuth_deg : {140.0, 200.0, 263.0}) {
      const SunAngles sun{azimuth_deg * kDeg, elevation_deg * kDeg};
      const double floor = sun_sweep_floor(sun.elevation, o);
      ASSERT_TRUE(std::isfinite(floor) && floor > 0.0);
      const horizon::Heading u = horizon::heading_from_geographic(sun.azimuth);
      const auto full = horizon::sweep_far_slopes(f, u, o.march, 1);
      const auto floored = horizon::sweep_far_slopes(f, u, o.march, 1, floor);
      const auto product = shadow_fraction_field(f, sun, o);
      auto fraction = [&](int i, int j, std::uint16_t code) {
        const double sigma = std::clamp(horizon::sweep_max_elevation(f, i, j, u, code, o.march), -kPi / 2, kPi / 2);
        const double y[2] = {(sigma - sun.elevation) / kR, (sigma - sun.elevation) / kR}, x[2] = {-1.0, 1.0};
        const sky::DiscLine tangent = sky::tangent_plane_line(horizon::horn_normal(f, i, j), sun.azimuth, sun.elevation, kR);
        return tangent.offset <= -1.0 ? 0.0 : sky::disc_fraction_above_polyline(x, y, &tangent);
      };
      for (int j = 0; j < f.height; ++j)
        for (int i = 0; i < f.width; ++i) {
          const std::size_t t = static_cast<std::size_t>(j) * f.width + i;
          const double exact = fraction(i, j, full[t]);
          ASSERT_EQ(fraction(i, j, floored[t]), exact) << elevation_deg << "° " << azimuth_deg << "° texel " << i << ", " << j;
          ASSERT_EQ(product[t], static_cast<float>(exact)) << elevation_deg << "° " << azimuth_deg << "°";
          lowered += floored[t] != full[t];
          partial += exact > 0.0 && exact < 1.0;
        }
    }
  EXPECT_GT(lowered, f.size());  // the floor did lower codes (of 9 suns' fields)
  EXPECT_GT(partial, 50u);       // and penumbrae were compared
}

TEST(SunShadow, NodataIsNanAndOptionsAreValidated) {
  auto f = test::make_field(8, 8, 10.0);
  f.valid[3 * 8 + 2] = 0;
  const auto v = shadow_fraction_field(f, {1.0, 20 * kDeg});
  EXPECT_TRUE(std::isnan(at(v, f, 2, 3)));
  EXPECT_FLOAT_EQ(at(v, f, 3, 3), 1.0f);
  SunShadowOptions bad;
  bad.radius = 0.0;
  EXPECT_THROW(shadow_fraction_field(f, {1.0, 0.1}, bad), std::invalid_argument);
  bad = {};
  bad.horizon = SunHorizon::Exact;
  bad.exact_columns = 1;
  EXPECT_THROW(shadow_fraction_field(f, {1.0, 0.1}, bad), std::invalid_argument);
  bad = {};
  bad.march.azimuths = 0;
  EXPECT_THROW(shadow_fraction_field(f, {1.0, 0.1}, bad), std::invalid_argument);
  EXPECT_THROW(shadow_fraction_field(f, {1.0, 2.0}), std::invalid_argument);
}

TEST(SunIrradiance, CosineTimesDniTimesFraction) {
  const glm::dvec3 up{0, 0, 1};
  const glm::dvec3 s = sun_direction({0.5, 30 * kDeg});
  EXPECT_NEAR(glm::length(s), 1.0, 1e-15);
  EXPECT_NEAR(s.z, 0.5, 1e-15);
  EXPECT_NEAR(sun_irradiance(up, s, 800.0, 0.5), 200.0, 1e-12);
  EXPECT_DOUBLE_EQ(sun_irradiance(-up, s, 800.0, 1.0), 0.0);  // sun behind the surface
  const sky::Sun sun = sky::make_sun(s, 3.0);
  const sky::Rgb e = sun_irradiance(up, sun, 0.25);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(e[k], sun.dni[k] * 0.5 * 0.25, 1e-9);
}

}  // namespace
}  // namespace skylit::shading
