// SH projection of skies: coefficients against an independent dense midpoint
// θ × φ quadrature, irradiance identities (√(4π/3)·L_10, clamped-cosine ZH),
// orientation of the frame, z-rotation consistency, and windowing.
#include "shading/sh/sh_basis.h"
#include "shading/sh/sh_rotation.h"
#include "shading/sh/zonal.h"
#include "shading/sky/sky_cie.h"
#include "shading/sky/sky_model.h"
#include "shading/sky/sky_preetham.h"
#include "shading/sky/sky_sh.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "hemisphere_quadrature.h"

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace skylit;
using namespace skylit::sky;

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

// Independent reference: midpoint rule in θ ∈ [0, π/2] (sin θ weight) × φ.
RgbSh midpoint_projection(const SkyModel& sky, int order, int nt, int np) {
  RgbSh out;
  const int nc = sh::num_coeffs(order);
  for (auto& v : out.c) v.assign(nc, 0.0);
  skylit::testing::for_each_upper_hemisphere_cell(nt, np, [&](const glm::dvec3& d, double dw) {
    const Rgb L = sky.radiance(d) * dw;
    const sh::Vec y = sh::eval_basis(order, d);
    for (int c = 0; c < 3; ++c)
      for (int i = 0; i < nc; ++i) out.c[c][i] += L[c] * y[i];
  });
  return out;
}

double max_abs_diff(const RgbSh& a, const RgbSh& b) {
  double e = 0.0;
  for (int c = 0; c < 3; ++c)
    for (std::size_t i = 0; i < a.c[c].size(); ++i) e = std::max(e, std::abs(a.c[c][i] - b.c[c][i]));
  return e;
}
}  // namespace

TEST(SkySh, HemisphereRuleWeightsAndExactness) {
  const auto r = upper_hemisphere_rule(8, 16);
  double w = 0.0, z2 = 0.0;
  for (std::size_t k = 0; k < r.dirs.size(); ++k) {
    w += r.weights[k];
    z2 += r.weights[k] * r.dirs[k].z * r.dirs[k].z;
    EXPECT_GT(r.dirs[k].z, 0.0);
  }
  EXPECT_NEAR(w, 2 * kPi, 1e-13);
  EXPECT_NEAR(z2, 2 * kPi / 3, 1e-13);
}

TEST(SkySh, UniformSkyClosedForm) {
  // L·[z > 0]: L_00 = L·2π/√(4π) = L√π, L_10 = L·√(3/(4π))·π, E = πL for every order ≥ 2.
  const UniformSky sky(Rgb(1.5));
  for (int order = 2; order <= 8; ++order) {
    const RgbSh s = project_sky(sky, order, 32, 64);
    EXPECT_NEAR(s.c[1][0], 1.5 * std::sqrt(kPi), 1e-12);
    EXPECT_NEAR(s.c[1][2], 1.5 * std::sqrt(3 / (4 * kPi)) * kPi, 1e-12);
    EXPECT_NEAR(horizontal_irradiance(s).g, 1.5 * kPi, 1e-12);
    for (int i = 1; i < sh::num_coeffs(order); ++i)
      if (sh::index(sh::band_of(i), 0) != i) {
        EXPECT_NEAR(s.c[0][i], 0.0, 1e-12);  // m ≠ 0 vanish
      }
  }
}

TEST(SkySh, ClampedCosineZhClosedForms) {
  const auto z = sh::clamped_cosine_zh(8);  // shading/sh/zonal.h
  const double sp = std::sqrt(kPi);
  const double expected[8] = {sp / 2, std::sqrt(kPi / 3), std::sqrt(5 * kPi) / 8, 0, -sp / 16, 0, std::sqrt(13 * kPi) / 128, 0};
  for (int l = 0; l < 8; ++l) EXPECT_NEAR(z[l], expected[l], 1e-14) << l;
}

TEST(SkySh, ProjectionMatchesDenseMidpointQuadrature) {
  const auto sun = direction_from_azimuth_elevation(130 * kDeg, 35 * kDeg);
  const PreethamSky pre(sun, 2.5);
  const CieSky cie(12, sun, Rgb(10.0));
  for (const SkyModel* sky : {static_cast<const SkyModel*>(&pre), static_cast<const SkyModel*>(&cie)}) {
    const RgbSh a = project_sky(*sky, 8);
    const RgbSh b = midpoint_projection(*sky, 8, 300, 600);
    const double scale = std::abs(a.c[1][0]);
    EXPECT_LT(max_abs_diff(a, b), 1e-4 * scale);
    std::printf("max |GL − midpoint| / L_00 = %.2e\n", max_abs_diff(a, b) / scale);
  }
}

TEST(SkySh, HorizontalIrradianceFromShMatchesDirectIntegral) {
  for (double el : {5.0, 30.0, 60.0, 85.0}) {
    const PreethamSky sky(direction_from_azimuth_elevation(200 * kDeg, el * kDeg), 3.0);
    const Rgb direct = horizontal_irradiance(sky, 400, 800);
    for (int order : {2, 4, 8}) {
      const RgbSh s = project_sky(sky, order);
      const Rgb e = horizontal_irradiance(s);  // √(4π/3)·L_10: exact for a sky that is 0 below the horizon
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(e[c], direct[c], 2e-4 * direct[c]) << el << " " << order;
      // The clamped-cosine route agrees only up to the ZH tail beyond the order.
      if (order == 8) {
        EXPECT_NEAR(irradiance(s, {0, 0, 1}).g, direct.g, 0.02 * direct.g);
      }
    }
  }
}

TEST(SkySh, TiltedIrradianceMatchesDirectIntegral) {
  // Surface facing east, tilted 40°: E = ∫ L max(n·ω, 0) dω; order 8 keeps the ZH tail ≲ 2%.
  const CieSky sky(13, direction_from_azimuth_elevation(100 * kDeg, 40 * kDeg), Rgb(1.0));
  const glm::dvec3 n = direction_from_azimuth_elevation(90 * kDeg, 50 * kDeg);
  double direct = 0.0;
  const auto rule = upper_hemisphere_rule(400, 800);
  for (std::size_t k = 0; k < rule.dirs.size(); ++k)
    direct += rule.weights[k] * sky.radiance(rule.dirs[k]).g * std::max(0.0, glm::dot(n, rule.dirs[k]));
  EXPECT_NEAR(irradiance(project_sky(sky, 8), n).g, direct, 0.02 * direct);
}

TEST(SkySh, FrameOrientationEastSunGivesNegativeL11) {
  // y_{1,1} = −0.4886·x (CS phase) and x is east: a sky bright in the east has L_{1,1} < 0.
  const CieSky sky(12, direction_from_azimuth_elevation(90 * kDeg, 20 * kDeg), Rgb(1.0));
  const RgbSh s = project_sky(sky, 2);
  EXPECT_LT(s.c[0][sh::index(1, 1)], 0.0);
  EXPECT_NEAR(s.c[0][sh::index(1, -1)], 0.0, 1e-6 * s.c[0][0]);  // symmetric about the east–west axis
  const auto east = direction_from_azimuth_elevation(90 * kDeg, 20 * kDeg);
  const auto west = direction_from_azimuth_elevation(270 * kDeg, 20 * kDeg);
  EXPECT_GT(reconstruct(s, east).r, reconstruct(s, west).r);
}

TEST(SkySh, MovingTheSunEqualsRotatingTheCoefficients) {
  // The sun moving clockwise by ΔA (geographic) rotates the sky by −ΔA in φ.
  const double a0 = 40 * kDeg, da = 75 * kDeg;
  const RgbSh s0 = project_sky(PreethamSky(direction_from_azimuth_elevation(a0, 30 * kDeg), 4.0), 6);
  const RgbSh s1 = project_sky(PreethamSky(direction_from_azimuth_elevation(a0 + da, 30 * kDeg), 4.0), 6);
  const sh::Vec r = sh::rotate_z(s0.c[2], -da);
  double err = 0.0;
  for (std::size_t i = 0; i < r.size(); ++i) err = std::max(err, std::abs(r[i] - s1.c[2][i]));
  EXPECT_LT(err, 1e-4 * s0.c[2][0]);
}

TEST(SkySh, WindowWeights) {
  const auto h = window_weights(Window::Hanning, 4), l = window_weights(Window::Lanczos, 4);
  EXPECT_DOUBLE_EQ(h[0], 1.0);
  EXPECT_NEAR(h[2], 0.5, 1e-15);                  // (1 + cos(π/2))/2
  EXPECT_NEAR(l[2], 2 / kPi, 1e-15);              // sin(π/2)/(π/2)
  EXPECT_NEAR(h[1], (1 + std::sqrt(0.5)) / 2, 1e-15);
  for (double w : window_weights(Window::None, 8)) EXPECT_EQ(w, 1.0);
}

TEST(SkySh, WindowedClearSkyIsNotNegativeOverTheUpperHemisphere) {
  // A low clear-sky sun puts a sharp peak near the horizon, the worst case for ringing.
  for (double el : {5.0, 25.0, 60.0})
    for (int order : {3, 4, 6, 8}) {
      const PreethamSky sky(direction_from_azimuth_elevation(250 * kDeg, el * kDeg), 2.0);
      RgbSh s = project_sky(sky, order);
      const double mean = s.c[2][0] / std::sqrt(4 * kPi);  // DC value of blue
      double raw_min = 1e300, win_min = 1e300;
      RgbSh w = s;
      apply_window(w, Window::Hanning);
      for (int i = 0; i <= 45; ++i)
        for (int j = 0; j < 72; ++j) {
          const auto d = direction_from_azimuth_elevation(j * 5 * kDeg, i * 2 * kDeg);
          const Rgb a = reconstruct(s, d), b = reconstruct(w, d);
          raw_min = std::min({raw_min, a.r, a.g, a.b});
          win_min = std::min({win_min, b.r, b.g, b.b});
        }
      std::printf("elev %4.0f order %d: min raw %+.3f, Hanning %+.3f (× DC)\n", el, order, raw_min / mean, win_min / mean);
      EXPECT_GE(win_min, -0.01 * mean) << el << " " << order;
    }
}
