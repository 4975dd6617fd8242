// The multi-resolution horizon march (SN08/NS09): its step schedule and level choice,
// the tangent-plane floor, Earth curvature and the maximum distance, and its accuracy on
// analytic scenes against the closed forms of horizon_scenes.h.
#include "horizon_scenes.h"

#include "shading/horizon/azimuth.h"
#include "shading/horizon/horizon_exact.h"
#include "shading/horizon/horizon_march.h"
#include "shading/horizon/surface_normals.h"
#include "shading/products.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

namespace skylit::horizon {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

MarchOptions flat_earth(MarchOptions o = {}) {
  o.curvature.enabled = false;
  return o;
}

std::vector<double> march_horizons(const HorizonMarcher& m, int i, int j, int w) {
  std::vector<double> s(w);
  for (int k = 0; k < w; ++k) s[k] = m.max_elevation(i, j, heading_from_geographic(band_azimuth(k, w)));
  return s;
}

TEST(MarchSchedule, GeometricStepsEndAtMaxDistanceAndStartWithinATexel) {
  const auto f = test::make_field(64, 64, 2.0);
  MarchOptions o;
  o.max_distance_m = 1000.0;
  const HorizonMarcher m(f, o);
  EXPECT_EQ(m.steps(), auto_march_levels(1000.0, 2.0, 4));
  EXPECT_EQ(m.steps(), 37);  // ⌈4·log2(500)⌉ + 1
  EXPECT_DOUBLE_EQ(m.max_distance(), 1000.0);
  EXPECT_LE(m.distance(0), 2.0);
  EXPECT_GT(m.distance(0), 2.0 / std::exp2(0.25));
  for (int s = 1; s < m.steps(); ++s) {
    EXPECT_NEAR(m.distance(s) / m.distance(s - 1), std::exp2(0.25), 1e-12);
    // Level texel ≈ distance·2^(−o_v) (clamped to the pyramid's levels).
    const double ideal = 4.0 * (std::log2(m.distance(s) / 2.0) - 2.0);
    EXPECT_TRUE(m.level_of_step(s) == std::lround(std::max(0.0, ideal)) || m.level_of_step(s) < ideal);
    EXPECT_GE(m.level_of_step(s), m.level_of_step(s - 1));
  }
}

TEST(MarchSchedule, DefaultMaxDistanceIsTheDemExtent) {
  const auto f = test::make_field(30, 40, 5.0);
  const HorizonMarcher m(f, MarchOptions{});
  EXPECT_DOUBLE_EQ(m.max_distance(), std::hypot(150.0, 200.0));
}

TEST(MarchOptionsValidation, RejectsNonsense) {
  const auto f = test::make_field(8, 8, 1.0);
  MarchOptions o;
  o.azimuths = 0;
  EXPECT_THROW(HorizonMarcher(f, o), std::invalid_argument);
  o = {};
  o.k_v = 0;
  EXPECT_THROW(HorizonMarcher(f, o), std::invalid_argument);
  o = {};
  o.max_distance_m = -1;
  EXPECT_THROW(HorizonMarcher(f, o), std::invalid_argument);
}

TEST(TangentPlaneFloor, IsTheTangentPlaneNotNs09sArcsine) {
  // math-notes §10.14: a 60° tilt seen at 45° from its steepest descent.
  const double t = 60 * kDeg;
  const glm::dvec3 n(std::sin(t), 0.0, std::cos(t));  // faces east
  const Heading u = heading_from_math(45 * kDeg);
  EXPECT_NEAR(tangent_plane_floor(n, u) / kDeg, -50.768, 1e-3);
  EXPECT_NEAR(std::asin(n.x * u.east) / kDeg, 37.761, 1e-3);  // NS09's value, for contrast
  EXPECT_NEAR(tangent_plane_floor(n, heading_from_math(kPi)), t, 1e-12);  // uphill: +60°
}

TEST(HorizonMarch, FlatPlaneIsExactlyHorizontal) {
  const auto f = test::make_field(65, 65, 1.0);
  for (bool smooth : {true, false}) {
    MarchOptions o = flat_earth();
    o.smooth_max = smooth;
    const HorizonMarcher m(f, o);
    for (double s : march_horizons(m, 10, 40, 16)) EXPECT_NEAR(s, 0.0, 1e-6);
  }
}

TEST(HorizonMarch, SmoothMaxNeverExceedsPlainMax) {
  const int n = 129;
  const auto f = test::radial_pit(n, 1.0, 8, 40, 20);
  MarchOptions smooth = flat_earth(), plain = flat_earth();
  smooth.smooth_max = true;
  plain.smooth_max = false;
  const HorizonMarcher ms(f, smooth), mp(f, plain);
  int lower = 0;
  for (int k = 0; k < 16; ++k) {
    const Heading u = heading_from_geographic(band_azimuth(k, 16));
    const double s = ms.max_elevation(70, 50, u), p = mp.max_elevation(70, 50, u);
    EXPECT_LE(s, p + 1e-12) << "heading " << k;
    lower += s < p - 1e-9;
  }
  EXPECT_GT(lower, 0) << "the smooth max equals the plain max on every heading";
}

TEST(HorizonMarch, NoStepOnTheGridGivesMinusInfinity) {
  const auto f = test::make_field(16, 16, 1.0);
  const HorizonMarcher m(f, flat_earth());
  EXPECT_EQ(m.max_elevation(15, 4, heading_from_geographic(kPi / 2)), -std::numeric_limits<double>::infinity());
}

// Default parameters (W = 32, k_v = 4, o_v = 2, B-spline max, pyramid) against the
// closed forms. Tolerances: the pyramid level read at distance t has texels t/4 wide
// and its B-spline prefilter spans ±2 such texels, so features narrower than ~t/2 are
// rounded off (a sharp rim or wall top is lowered), and the smooth max lowers isolated
// peaks by up to a third of their excess over the neighbouring steps: horizons come out
// low, sky-view factors high. Each tolerance is the measured error of the scene (in the
// comment) with a ~50% margin, not a bound; real DEMs show a skyview RMSE of about 0.01
// (docs/accuracy.md).

TEST(HorizonMarchAccuracy, TiltedPlaneAwayFromTheEdges) {
  const double s = 25 * kDeg;
  const auto f = test::tilted_plane(129, 1.0, s);
  MarchOptions o = flat_earth();
  o.max_distance_m = 24.0;  // keep every sample's prefilter support inside the grid
  // Every way of reading heights reproduces a plane (the prefilter and both interpolants do).
  for (LevelSampling sampling : all_level_samplings()) {
    set_level_sampling(o, sampling);
    const HorizonMarcher m(f, o);
    const auto sigma = march_horizons(m, 64, 64, 32);
    EXPECT_NEAR(sigma[8], s, 2e-3) << level_sampling_name(sampling);  // uphill (east)
    EXPECT_NEAR(shading::skyview_from_horizon(sigma, horn_normal(f, 64, 64)), (1 + std::cos(s)) / 2, 1e-3)
        << level_sampling_name(sampling);
  }
}

TEST(HorizonMarch, LevelSamplingNamesRoundTrip) {
  for (LevelSampling sampling : all_level_samplings()) {
    EXPECT_EQ(parse_level_sampling(level_sampling_name(sampling)), sampling);
    MarchOptions o;
    set_level_sampling(o, sampling);
    EXPECT_EQ(level_sampling(o), sampling);
  }
  EXPECT_FALSE(parse_level_sampling("bicubic").has_value());
}

TEST(HorizonMarchAccuracy, CircularPitCentre) {
  const int n = 129;
  const double r0 = 8, r1 = 40, depth = 20;
  const auto f = test::radial_pit(n, 1.0, r0, r1, depth);
  const double gamma = test::pit_rim_elevation(r0, r1, depth, 64.0);
  const HorizonMarcher m(f, flat_earth());
  const auto sigma = march_horizons(m, n / 2, n / 2, 32);
  // Measured: rim 0.471 vs γ = 0.494 rad, svf +0.021, skyview +0.019.
  for (double v : sigma) EXPECT_NEAR(v, gamma - 0.02, 0.02);
  EXPECT_NEAR(shading::svf_from_horizon(sigma), 1 - std::sin(gamma), 0.03);
  EXPECT_NEAR(shading::skyview_from_horizon(sigma, {0, 0, 1}), std::pow(std::cos(gamma), 2), 0.03);
}

TEST(HorizonMarchAccuracy, FiniteWall) {
  // A thick wall (a plateau edge, 24 texels deep): thin walls are flattened by the
  // prefilter altogether (see ThinFeaturesFadeWithDistance).
  const int n = 97;
  const double dx = 2.0, height = 30.0;
  const int col0 = 8, thick = 24, half_rows = 16, d_texels = 24;
  const auto f = test::wall(n, dx, col0, thick, half_rows, height);
  const int ir = col0 + thick - 1 + d_texels, jr = n / 2;
  const double a = height / (d_texels * dx);
  const double psi_l = std::atan((half_rows + 0.5) / d_texels);
  const HorizonMarcher m(f, flat_earth());
  const auto sigma = march_horizons(m, ir, jr, 32);
  // Measured: skyview +0.027, svf +0.031 (the edge, blurred over ±t/2, looks lower).
  EXPECT_NEAR(shading::skyview_from_horizon(sigma, {0, 0, 1}), test::wall_skyview(a, psi_l), 0.045);
  EXPECT_NEAR(shading::svf_from_horizon(sigma), test::wall_svf(a, psi_l), 0.045);
}

TEST(HorizonMarchAccuracy, ThinFeaturesFadeWithDistance) {
  // A one-texel wall 10 texels away is read from a level with 2.4-texel texels: its
  // prefiltered height, and so its elevation, drops to a fraction (documented
  // behaviour of the pyramid, docs/accuracy.md); the exact march sees 45°.
  auto f = test::make_field(41, 41, 1.0);
  for (int j = 0; j < 41; ++j) f.at(30, j) = 10.0f;
  const Heading east = heading_from_geographic(kPi / 2);
  const double marched = HorizonMarcher(f, flat_earth()).max_elevation(20, 20, east);
  ExactMarch exact;
  exact.curvature.enabled = false;
  EXPECT_NEAR(exact_max_elevation(f, 20, 20, east, exact), kPi / 4, 1e-12);
  EXPECT_GT(marched, 0.1);  // measured 0.42 rad (0.22 with B-spline levels and smooth max)
  EXPECT_LT(marched, 0.6);
  MarchOptions sharp = flat_earth();
  sharp.use_pyramid = false;
  sharp.smooth_max = false;  // level 0, plain max: only the step spacing can miss it
  EXPECT_GT(HorizonMarcher(f, sharp).max_elevation(20, 20, east), 0.6);
}

TEST(HorizonMarch, EarthCurvatureOnAFlatPlane) {
  // No terrain above the receiver: every step is lowered by t²/(2R_eff), so the
  // largest blocking angle is the first step's, −atan(t₀/(2R_eff)).
  const auto f = test::make_field(65, 65, 1000.0);
  MarchOptions o;
  o.smooth_max = false;
  const HorizonMarcher m(f, o);
  const double r_eff = o.curvature.effective_radius();
  EXPECT_NEAR(m.max_elevation(32, 32, heading_from_geographic(1.0)), -std::atan(m.distance(0) / (2 * r_eff)),
              1e-12);
}

TEST(HorizonMarch, MaxDistanceIsHonoured) {
  // A plateau edge 100 m west of the receiver; with D = 30 m no step (nor its
  // prefilter, ±2 level texels of ≤ 30/4 m) reaches it — only the exponentially
  // decaying tail of the interpolating B-spline's coefficients does (< 1e-6 rad).
  const auto f = test::wall(201, 1.0, 0, 23, 100, 50.0);
  const Heading west = heading_from_geographic(1.5 * kPi);
  MarchOptions o = flat_earth();
  o.max_distance_m = 30.0;
  EXPECT_NEAR(HorizonMarcher(f, o).max_elevation(122, 100, west), 0.0, 1e-6);
  o.max_distance_m = 0.0;  // DEM extent: the edge is seen (atan(50/100) = 0.46 less blur)
  EXPECT_GT(HorizonMarcher(f, o).max_elevation(122, 100, west), 0.2);  // measured 0.257
  o.use_pyramid = false;  // level 0 only, no prefilter: sharp at the limit
  o.max_distance_m = 99.0;
  EXPECT_EQ(HorizonMarcher(f, o).max_elevation(122, 100, west), 0.0);
  o.max_distance_m = 100.0;
  o.smooth_max = false;
  EXPECT_NEAR(HorizonMarcher(f, o).max_elevation(122, 100, west), std::atan(0.5), 1e-12);
}

// The exit's height bound: above the largest height, NaN (nodata) skipped, and no exit
// (+inf) where there is no height to bound.
TEST(HorizonMarch, ExitHeightBoundSkipsNodataAndNeverUndercuts) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<float> heights = {120.0f, nan, 2500.5f, -30.0f};
  const double bound = horizon::march_exit_height_bound(heights);
  EXPECT_GT(bound, 2500.5);
  EXPECT_LT(bound, 2500.5 + 1.0);
  const std::vector<float> none = {nan, nan};
  EXPECT_EQ(horizon::march_exit_height_bound(none), std::numeric_limits<double>::infinity());
  EXPECT_EQ(horizon::march_exit_height_bound(std::span<const float>()), std::numeric_limits<double>::infinity());
}

// The early exit (MarchExitSlack) must return exactly what the full march returns, on
// scenes where it fires (pit, wall, plane, rough ground) and where it cannot (flat), for
// both maxima and every level sampling, and save steps somewhere.
TEST(HorizonMarch, EarlyExitGivesExactlyTheFullMarch) {
  std::vector<terrain::HeightField> scenes;
  scenes.push_back(test::radial_pit(65, 2.0, 6, 20, 15));
  scenes.push_back(test::wall(65, 2.0, 20, 3, 12, 30.0));
  scenes.push_back(test::tilted_plane(65, 2.0, 10 * kDeg));
  scenes.push_back(test::make_field(33, 33, 1.0));
  auto rough = test::make_field(65, 65, 5.0);
  std::uint32_t state = 12345;  // LCG: heights in [0, 100) m
  for (float& z : rough.heights) z = static_cast<float>((state = state * 1664525u + 1013904223u) >> 8) * 100.0f / 16777216.0f;
  scenes.push_back(std::move(rough));
  long full_steps = 0, exit_steps = 0;
  for (const auto& f : scenes)
    for (bool smooth : {true, false})
      for (LevelSampling sampling : all_level_samplings()) {
        MarchOptions o;
        o.smooth_max = smooth;
        set_level_sampling(o, sampling);
        const HorizonMarcher m(f, o);
        for (int j = 0; j < f.height; j += 3)
          for (int i = 0; i < f.width; i += 3)
            for (int k = 0; k < 16; ++k) {
              const Heading u = heading_from_geographic(band_azimuth(k, 16));
              int n_full = 0, n_exit = 0;
              const double full = m.max_elevation(i, j, u, false, &n_full);
              EXPECT_EQ(m.max_elevation(i, j, u, true, &n_exit), full) << i << "," << j << " k=" << k;
              full_steps += n_full, exit_steps += n_exit;
            }
      }
  EXPECT_LT(exit_steps, full_steps);
}

}  // namespace
}  // namespace skylit::horizon
