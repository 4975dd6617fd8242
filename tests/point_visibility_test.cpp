// Offset marching from a point above the terrain (shading/point_visibility.h) against
// closed forms derived here: open sky over a plane, a wall seen from above its foot
// (per azimuth and integrated), a radial pit's uniform rim, the sun behind a ridge and
// below the sea-level horizon; and the march's horizons against a dense ray scan
// written in this file, on a synthetic field.
#include "horizon_scenes.h"

#include "shading/horizon/horizon_march.h"
#include "shading/point_visibility.h"
#include "terrain/synthetic.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace {

using namespace skylit;
using shading::PointPlace;
using shading::PointVisibilityMarcher;
using shading::PointVisibilityOptions;
using shading::SunAngles;

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

PointVisibilityOptions flat_earth() {
  PointVisibilityOptions o;
  o.march.curvature.enabled = false;
  return o;
}

// The field-frame position of fractional texel (i, j) (renderer.h: (i·dx, −j·dy)).
glm::dvec3 at_texel(const terrain::HeightField& f, double i, double j, double z) { return {i * f.dx(0), -j * f.dy, z}; }

TEST(PointVisibility, OpenSkyAboveAPlane) {
  terrain::HeightField f(101, 101, 10.0);
  for (float& h : f.heights) h = 100.0f;
  const PointVisibilityMarcher m(f);  // curvature on: the plane falls away below the horizontal
  for (double z : {100.0, 150.0, 2000.0}) {
    const auto v = m.at(at_texel(f, 50.3, 49.6, z), SunAngles{2.0, 10.0 * kDeg});
    EXPECT_EQ(v.place, PointPlace::Above);
    EXPECT_NEAR(*v.ground_m, 100.0, 1e-9);
    EXPECT_EQ(v.horizon.size(), 32u);
    for (double s : v.horizon) EXPECT_LE(s, 0.0);
    EXPECT_DOUBLE_EQ(v.sky_view, 1.0);
    EXPECT_DOUBLE_EQ(v.sky_fraction, 1.0);
    ASSERT_TRUE(v.sun);
    EXPECT_FALSE(v.sun->in_shadow);
    EXPECT_DOUBLE_EQ(v.sun->visible_fraction, 1.0);
  }
}

TEST(PointVisibility, AtATexelCentreOnTheGroundItIsTheTexelsMarch) {
  const auto f = test::radial_pit(65, 1.0, 4, 20, 12);
  const horizon::HorizonMarcher m(f, shading::sun_march_options());
  for (int k = 0; k < 8; ++k) {
    const auto u = horizon::heading_from_geographic(k * kPi / 4 + 0.1);
    EXPECT_EQ(m.max_elevation_from({40.0, 29.0}, f.at(40, 29), u), m.max_elevation(40, 29, u));
  }
}

// test::wall (horizon_scenes.h): a plateau edge whose east face top is column 30's
// centre, rows c ± 49 (c = 70), 100 m high, dx = 2 m. The point, 19 m up at texel
// (70.5, 70.25), is D = 81 m east of the face: a = (H − z)/D = 1. Along ψ from due west
// the face top is the ray's steepest point (the bilinear ramp under it is linear), so
// σ(ψ) = atan(a·cos ψ) while the ray meets the wall (|ψ| < ψ_L = atan(98/81) = 50.4°);
// elsewhere the ground lies below the point (σ < 0). A march's first sample past the
// face, at t* = D/cos ψ, lies within its step beyond it, so
// tan σ_marched ∈ [a·cos ψ·t*/t_next, a·cos ψ], t_next ≤ t* + 1 m (dense: half a 2 m
// texel along the dominant axis, ≤ 1 m at |ψ| ≤ 45°) or t*·2^(1/k_v) (the schedule).
struct WallScene {
  terrain::HeightField f = test::wall(141, 2.0, 7, 24, 49, 100.0);
  glm::dvec3 point = at_texel(f, 70.5, 70.25, 19.0);
  double a = 1.0, d = 81.0;
  double psi_l = std::atan(98.0 / 81.0);
  // ψ of band k of W (geographic azimuth k·2π/W), from due west, in (−π, π].
  static double psi(int k, int w) { return std::remainder(2 * kPi * k / w - 1.5 * kPi, 2 * kPi); }
  // The bound above: the smallest t*/t_next of the options' march at ψ.
  double gap(const PointVisibilityOptions& o, double psi) const {
    const double t = d / std::cos(psi);
    return o.dense ? t / (t + 1.0) : std::exp2(-1.0 / o.march.k_v);
  }
};

void expect_wall(const PointVisibilityOptions& o) {
  const WallScene s;
  const auto v = PointVisibilityMarcher(s.f, o).at(s.point);
  ASSERT_EQ(v.place, PointPlace::Above);
  const int w = static_cast<int>(v.horizon.size());
  double lo = 0.0, hi = 0.0, svf_lo = 0.0, svf_hi = 0.0;  // bounds of the sums (1/W)Σ
  for (int k = 0; k < w; ++k) {
    const double psi = WallScene::psi(k, w);
    if (std::abs(psi) < s.psi_l) {
      const double t = s.a * std::cos(psi), t_lo = t * s.gap(o, psi);
      EXPECT_LE(std::tan(v.horizon[k]), t + 1e-9) << k;
      EXPECT_GE(std::tan(v.horizon[k]), t_lo - 1e-9) << k;
      hi += 1.0 / (1.0 + t_lo * t_lo), lo += 1.0 / (1.0 + t * t);  // cos²(atan x) = 1/(1 + x²)
      svf_hi += 1.0 - std::sin(std::atan(t_lo)), svf_lo += 1.0 - std::sin(std::atan(t));
    } else {
      EXPECT_LT(v.horizon[k], 0.0) << k;
      lo += 1.0, hi += 1.0, svf_lo += 1.0, svf_hi += 1.0;
    }
  }
  EXPECT_GE(v.sky_view, lo / w - 1e-12);
  EXPECT_LE(v.sky_view, hi / w + 1e-12);
  EXPECT_GE(v.sky_fraction, svf_lo / w - 1e-12);
  EXPECT_LE(v.sky_fraction, svf_hi / w + 1e-12);
  // The integrals over ψ in closed form (horizon_scenes.h): the W-slice sums above differ
  // from them by the midpoint rule (a wall end falls inside a slice).
  EXPECT_NEAR(lo / w, test::wall_skyview(s.a, s.psi_l), 0.01);
  EXPECT_NEAR(svf_lo / w, test::wall_svf(s.a, s.psi_l), 0.01);
  std::printf("wall (%s): sky_view %.5f, closed form %.5f, W-slice sum %.5f..%.5f\n", o.dense ? "dense" : "schedule",
              v.sky_view, test::wall_skyview(s.a, s.psi_l), lo / w, hi / w);
}

TEST(PointVisibility, WallSeenFromAbove) {
  PointVisibilityOptions o = flat_earth();
  expect_wall(o);
  o.dense = false;
  expect_wall(o);
}

TEST(PointVisibility, SunBehindTheRidgeIsShadowedAndJustAboveItIsLit) {
  const WallScene s;
  const PointVisibilityOptions o = flat_earth();
  const PointVisibilityMarcher m(s.f, o);
  // Due west (ψ = 0) the ridge stands at atan(a) = 45°, the march within the bound above
  // (0.35°); the disc's radius is 0.27°.
  const double west = 1.5 * kPi, ridge = std::atan(s.a), low = std::atan(s.a * s.gap(o, 0.0));
  const auto behind = m.at(s.point, SunAngles{west, ridge - 1.0 * kDeg});
  ASSERT_TRUE(behind.sun);
  EXPECT_TRUE(behind.sun->in_shadow);
  EXPECT_TRUE(behind.sun->terrain_horizon);
  EXPECT_EQ(behind.sun->visible_fraction, 0.0);
  const auto above = m.at(s.point, SunAngles{west, ridge + 0.5 * kDeg});
  EXPECT_FALSE(above.sun->in_shadow);
  EXPECT_EQ(above.sun->visible_fraction, 1.0);
  EXPECT_GE(above.sun->margin, 0.5 * kDeg - 1e-9);
  EXPECT_LE(above.sun->margin, 0.5 * kDeg + ridge - low + 1e-9);
  // Past the wall's end a low sun is open.
  const auto past = m.at(s.point, SunAngles{west + 70 * kDeg, 2.0 * kDeg});
  EXPECT_FALSE(past.sun->in_shadow);
  EXPECT_EQ(past.sun->visible_fraction, 1.0);
  // A sun centred on the horizon shows half its disc.
  const double sigma = above.sun->horizon;
  const auto half = m.at(s.point, SunAngles{west, sigma});
  EXPECT_NEAR(half.sun->visible_fraction, 0.5, 1e-12);
}

// The seen horizon of a sphere of radius R from height z above it, by brute force: the
// largest elevation of its surface points at central angle θ, observer at (0, R + z).
double sphere_dip(double r, double z) {
  double best = -kPi / 2;
  for (double th = 1e-7; th < 0.2; th += 1e-7)
    best = std::max(best, std::atan2(r * std::cos(th) - (r + z), r * std::sin(th)));
  return best;
}

TEST(PointVisibility, ASunBelowTheSeaLevelHorizonIsNight) {
  terrain::HeightField f(101, 101, 10.0);
  const PointVisibilityMarcher m(f);
  const double z = 3000.0, r = m.options().march.curvature.effective_radius();
  const double dip = sphere_dip(r, z);  // ≈ −1.64°
  EXPECT_NEAR(shading::sea_level_horizon(z, m.options().march.curvature), dip, 1e-6);
  const auto night = m.at(at_texel(f, 50, 50, z), SunAngles{1.0, dip - 0.5 * kDeg});
  EXPECT_TRUE(night.sun->in_shadow);
  EXPECT_FALSE(night.sun->terrain_horizon);  // the DEM is far below: the floor decides
  EXPECT_EQ(night.sun->visible_fraction, 0.0);
  const auto dusk = m.at(at_texel(f, 50, 50, z), SunAngles{1.0, dip + 0.5 * kDeg});
  EXPECT_FALSE(dusk.sun->in_shadow);
  EXPECT_EQ(dusk.sun->visible_fraction, 1.0);
  EXPECT_DOUBLE_EQ(night.sky_view, 1.0);
}

// test::radial_pit from above its floor: the rim is at the same elevation γ on every
// azimuth, so sky_view = cos²γ and sky_fraction = 1 − sin γ. γ by a dense 1-D search of
// the radial profile (the pit is smooth: bilinear errs by ≤ h''·dx²/8).
TEST(PointVisibility, UniformRimOfAPit) {
  const double r0 = 6, r1 = 40, depth = 30, lift = 8;  // the point 8 m above the floor
  const auto f = test::radial_pit(129, 1.0, r0, r1, depth);
  double gamma = -1.0;
  for (double t = 1e-3; t <= 64.0; t += 1e-3)
    gamma = std::max(gamma, std::atan((test::pit_profile(t, r0, r1, depth) + depth - lift) / t));
  const PointVisibilityMarcher m(f, flat_earth());
  const auto v = m.at(at_texel(f, 64, 64, -depth + lift));
  ASSERT_EQ(v.place, PointPlace::Above);
  double worst = 0.0;
  for (double s : v.horizon) worst = std::max(worst, std::abs(s - gamma));
  // Measured: |σ_k − γ| ≤ 0.016°, sky_view 1.6e-4 above cos²γ.
  EXPECT_LT(worst, 0.1 * kDeg);
  EXPECT_NEAR(v.sky_view, std::cos(gamma) * std::cos(gamma), 1e-3);
  EXPECT_NEAR(v.sky_fraction, 1.0 - std::sin(gamma), 1e-3);
  std::printf("pit: gamma %.4f deg, worst |sigma - gamma| %.4f deg, sky_view %.6f vs cos² %.6f\n", gamma / kDeg,
              worst / kDeg, v.sky_view, std::cos(gamma) * std::cos(gamma));
}

TEST(PointVisibility, OutsideAndBelowGroundAreFlaggedAndFinite) {
  const auto f = test::radial_pit(65, 1.0, 4, 20, 12);
  const PointVisibilityMarcher m(f);
  const auto out = m.at({-30.0, 5.0, 100.0}, SunAngles{0.5, 0.3});
  EXPECT_EQ(out.place, PointPlace::Outside);
  EXPECT_FALSE(out.ground_m);
  EXPECT_TRUE(out.horizon.empty());
  EXPECT_EQ(out.sky_view, 1.0);
  EXPECT_FALSE(out.sun->in_shadow);
  EXPECT_FALSE(out.sun->terrain_horizon);
  const auto below = m.at(at_texel(f, 32, 32, -13.0), SunAngles{0.5, 0.3});
  EXPECT_EQ(below.place, PointPlace::BelowGround);
  EXPECT_EQ(below.sky_view, 0.0);
  EXPECT_EQ(below.sky_fraction, 0.0);
  EXPECT_TRUE(below.sun->in_shadow);
  EXPECT_EQ(below.sun->visible_fraction, 0.0);
  EXPECT_TRUE(std::isfinite(below.sun->margin));
  // A point on the grid's edge whose rays leave at once: finite horizons, no NaN.
  const auto edge = m.at(at_texel(f, 64, 0, 50.0), SunAngles{0.0, 0.1});
  EXPECT_EQ(edge.place, PointPlace::Above);
  for (double s : edge.horizon) EXPECT_TRUE(std::isfinite(s));
  EXPECT_TRUE(std::isfinite(edge.sky_view));
  EXPECT_THROW(m.at({std::nan(""), 0.0, 0.0}), std::invalid_argument);
}

// Bilinear height of texel coordinates (x, y) (centres at integers), written here.
double bilinear(const terrain::HeightField& f, double x, double y) {
  const int i = std::clamp(static_cast<int>(std::floor(x)), 0, f.width - 2);
  const int j = std::clamp(static_cast<int>(std::floor(y)), 0, f.height - 2);
  const double a = x - i, b = y - j;
  return (1 - b) * ((1 - a) * f.at(i, j) + a * f.at(i + 1, j)) + b * ((1 - a) * f.at(i, j + 1) + a * f.at(i + 1, j + 1));
}

// The horizon from (x, y) texels at height z along geographic azimuth A: every 1/50 of
// a texel to the grid's edge, curvature drop t²/(2 R_eff) included.
double dense_horizon(const terrain::HeightField& f, double x, double y, double z, double azimuth, double r_eff) {
  const double e = std::sin(azimuth), n = std::cos(azimuth), step = 0.02 * f.dy;
  double best = -kPi / 2;
  for (double t = step;; t += step) {
    const double px = x + t * e / f.dx(0), py = y - t * n / f.dy;
    if (px < 0 || py < 0 || px > f.width - 1 || py > f.height - 1) break;
    best = std::max(best, std::atan((bilinear(f, px, py) - t * t / (2 * r_eff) - z) / t));
  }
  return best;
}

// Mean and worst |dense scan − march| (rad) over 12 random points 2–600 m above a steep
// synthetic field (96² at 30 m, 1800 m of relief), 8 azimuths each.
struct ScanErrors {
  double mean = 0.0, worst = 0.0;
};
ScanErrors scan_errors(const PointVisibilityOptions& o) {
  terrain::SyntheticOptions so;
  so.width = so.height = 96;
  so.spacing = 30.0;
  so.seed = 7;
  const auto f = terrain::make_synthetic_terrain(so);
  const PointVisibilityMarcher m(f, o);
  const double r_eff = o.march.curvature.effective_radius();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> pos(5.0, 90.0), lift(2.0, 600.0);
  ScanErrors e;
  int n = 0;
  for (int p = 0; p < 12; ++p) {
    const double x = pos(rng), y = pos(rng);
    const double z = bilinear(f, x, y) + lift(rng);
    const auto v = m.at(at_texel(f, x, y, z));
    EXPECT_EQ(v.place, PointPlace::Above);
    for (int k = 0; k < 32; k += 4) {
      const double err = dense_horizon(f, x, y, z, 2 * kPi * k / 32, r_eff) - v.horizon[k];
      // A march samples a subset of the ray: never above the continuum's max, which the
      // dense scan approaches from below to within its 1/50-texel step.
      EXPECT_GE(err, -5e-4) << p << " " << k;
      e.worst = std::max(e.worst, std::abs(err)), e.mean += std::abs(err), ++n;
    }
  }
  e.mean /= n;
  std::printf("%s march against the dense scan: mean |error| %.4f deg, worst %.4f deg over %d horizons\n",
              o.dense ? "dense" : "scheduled", e.mean / kDeg, e.worst / kDeg, n);
  return e;
}

TEST(PointVisibility, HorizonsMatchADenseRayScan) {
  PointVisibilityOptions o;
  // At the scan's own step the march's geometry (origin, heading, bilinear heights,
  // curvature) must agree with it: only their different sample positions remain.
  o.dense_step_texels = 0.02;
  const ScanErrors fine = scan_errors(o);
  EXPECT_LT(fine.worst, 0.06 * kDeg);
  EXPECT_LT(fine.mean, 0.01 * kDeg);
  // The default half-texel step misses sharp crests by up to slope·step/2 in height:
  // measured mean 0.23°, worst 1.40° on this steep field (0.25 texel: 0.11°, 0.55°;
  // 0.1: 0.034°, 0.23°; 0.05: 0.013°, 0.070°).
  o.dense_step_texels = 0.5;
  const ScanErrors dense = scan_errors(o);
  EXPECT_LT(dense.mean, 0.3 * kDeg);
  EXPECT_LT(dense.worst, 1.6 * kDeg);
  // The schedule (2^(1/32) apart: 1.5 texels at the far side) does little worse here,
  // measured mean 0.26°, worst 1.43°; it skips whole texels on larger grids.
  o.dense = false;
  const ScanErrors scheduled = scan_errors(o);
  EXPECT_LT(scheduled.mean, 0.35 * kDeg);
  EXPECT_LT(scheduled.worst, 1.6 * kDeg);
}

}  // namespace
