// The exact (ground-truth) horizon march and the per-texel sky integrals, against
// closed forms on analytic scenes (horizon_scenes.h) and against the visibility oracle.
#include "horizon_scenes.h"

#include "shading/horizon/azimuth.h"
#include "shading/horizon/horizon_exact.h"
#include "shading/horizon/surface_normals.h"
#include "shading/products.h"
#include "shading/visibility_truth.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace skylit::horizon {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

ExactMarch flat_earth() {
  ExactMarch m;
  m.curvature.enabled = false;
  return m;
}

// Exact horizons at geographic azimuths A_k = k·2π/W of one texel.
std::vector<double> exact_horizons(const terrain::HeightField& f, int i, int j, int w, const ExactMarch& m) {
  std::vector<double> s(w);
  for (int k = 0; k < w; ++k) s[k] = exact_max_elevation(f, i, j, heading_from_geographic(band_azimuth(k, w)), m);
  return s;
}

TEST(AzimuthConvention, GeographicAndMathFramesAgree) {
  // North is +y (φ = π/2), east is +x (φ = 0), clockwise from north.
  const Heading north = heading_from_geographic(0.0), east = heading_from_geographic(kPi / 2);
  EXPECT_NEAR(north.north, 1.0, 1e-15);
  EXPECT_NEAR(east.east, 1.0, 1e-15);
  EXPECT_NEAR(math_from_geographic(kPi / 2), 0.0, 1e-15);
  EXPECT_NEAR(geographic_from_math(math_from_geographic(1.234)), 1.234, 1e-15);
  const Heading h = heading_from_math(math_from_geographic(0.7));
  EXPECT_NEAR(h.east, std::sin(0.7), 1e-15);
  EXPECT_NEAR(band_azimuth(8, 32), kPi / 2, 1e-15);
}

TEST(HornNormal, TiltedPlaneIsExactInsideAndHalvedSlopeAtReplicatedEdge) {
  const double s = 30 * kDeg;
  const auto f = test::tilted_plane(9, 2.0, s);
  const glm::dvec3 n = horn_normal(f, 4, 4);
  EXPECT_NEAR(n.x, -std::sin(s), 1e-6);
  EXPECT_NEAR(n.y, 0.0, 1e-12);
  EXPECT_NEAR(n.z, std::cos(s), 1e-6);
  // Edge replication: at the east edge the east neighbour is the texel itself.
  const glm::dvec3 e = horn_normal(f, 8, 4);
  EXPECT_NEAR(-e.x / e.z, std::tan(s) / 2, 1e-6);
}

TEST(HornNormal, UsesPerRowSpacing) {
  auto f = test::tilted_plane(5, 1.0, 45 * kDeg);  // rises 1 m per texel eastward
  f.dx_per_row = {1, 2, 4, 8, 16};
  const glm::dvec3 n = horn_normal(f, 2, 3);
  EXPECT_NEAR(-n.x / n.z, 1.0 / 8.0, 1e-12);
}

TEST(SkyviewSlice, MatchesVisibilityOracleWithTiltedNormal) {
  // A smooth horizon (some of it below 0, where the sky is absent) and a tilted normal:
  // the closed-form slice integral, summed over many azimuths, equals the oracle's
  // exact-in-elevation quadrature with the horizon clamped at 0.
  auto horizon_geo = [](double a) { return 0.25 + 0.3 * std::cos(a - 0.4) + 0.15 * std::sin(2 * a + 1); };
  const glm::dvec3 n = glm::normalize(glm::dvec3(0.4, -0.3, 0.85));
  const int w = 4096;
  std::vector<double> sigma(w);
  for (int k = 0; k < w; ++k) sigma[k] = horizon_geo(band_azimuth(k, w));
  shading::Occluders occ;
  occ.horizon = [&](double phi) { return std::max(0.0, horizon_geo(geographic_from_math(phi))); };
  EXPECT_NEAR(shading::skyview_from_horizon(sigma, n), shading::cosine_weighted_visibility(occ, n, 4096), 2e-6);
}

TEST(SkyviewSlice, OpenFlatAndTiltedGround) {
  EXPECT_NEAR(shading::skyview_from_horizon(std::vector<double>(7, 0.0), {0, 0, 1}), 1.0, 1e-14);
  EXPECT_NEAR(shading::svf_from_horizon(std::vector<double>(7, -0.1)), 1.0, 1e-15);
  // Below-horizontal horizons do not add sky.
  EXPECT_NEAR(shading::skyview_from_horizon(std::vector<double>(64, -0.3), {0, 0, 1}), 1.0, 1e-14);
  const double s = 40 * kDeg;
  EXPECT_NEAR(shading::skyview_from_horizon(std::vector<double>(360, 0.0), {std::sin(s), 0, std::cos(s)}),
              (1 + std::cos(s)) / 2, 1e-12);
}

TEST(ExactHorizon, FlatPlaneIsHorizontalAndOpen) {
  const auto f = test::make_field(33, 33, 10.0);
  const auto s = exact_horizons(f, 16, 16, 64, flat_earth());
  for (double v : s) EXPECT_EQ(v, 0.0);
  EXPECT_DOUBLE_EQ(shading::svf_from_horizon(s), 1.0);
  EXPECT_NEAR(shading::skyview_from_horizon(s, horn_normal(f, 16, 16)), 1.0, 1e-14);
}

TEST(ExactHorizon, TiltedPlaneSkyviewIsOnePlusCosOverTwo) {
  const double s = 25 * kDeg;
  const auto f = test::tilted_plane(41, 5.0, s);
  const auto sigma = exact_horizons(f, 20, 20, 720, flat_earth());
  // Uphill (east) the plane itself is the horizon.
  EXPECT_NEAR(sigma[180], s, 1e-6);
  EXPECT_NEAR(shading::skyview_from_horizon(sigma, horn_normal(f, 20, 20)), (1 + std::cos(s)) / 2, 1e-6);
}

TEST(ExactHorizon, CircularPitCentre) {
  // Rim elevation γ from the 1-D profile; svf = 1 − sin γ, skyview = cos²γ (n = z).
  const int n = 129;
  const double dx = 1.0, r0 = 8, r1 = 40, depth = 20;
  const auto f = test::radial_pit(n, dx, r0, r1, depth);
  const double gamma = test::pit_rim_elevation(r0, r1, depth, 64.0);
  const auto sigma = exact_horizons(f, n / 2, n / 2, 720, flat_earth());
  for (double v : sigma) EXPECT_NEAR(v, gamma, 1.5e-3);  // bilinear: ≤ h''dx²/8 / r ≈ 5e-4
  EXPECT_NEAR(shading::svf_from_horizon(sigma), 1 - std::sin(gamma), 1.5e-3);
  EXPECT_NEAR(shading::skyview_from_horizon(sigma, horn_normal(f, n / 2, n / 2)), std::pow(std::cos(gamma), 2), 1.5e-3);
}

TEST(ExactHorizon, FiniteWallMatchesClosedForm) {
  const int n = 97;
  const double dx = 2.0, height = 30.0;
  const int col0 = 30, thick = 3, half_rows = 16, d_texels = 24;
  const auto f = test::wall(n, dx, col0, thick, half_rows, height);
  const int ir = col0 + thick - 1 + d_texels, jr = n / 2;
  const double a = height / (d_texels * dx);
  const double psi_l = std::atan((half_rows + 0.5) / d_texels);  // ramp beyond the end rows counts half
  const auto sigma = exact_horizons(f, ir, jr, 2880, flat_earth());
  // Due west (A = 270°): the full wall height at distance D.
  EXPECT_NEAR(sigma[2160], std::atan(a), 1e-12);
  EXPECT_NEAR(shading::skyview_from_horizon(sigma, horn_normal(f, ir, jr)), test::wall_skyview(a, psi_l), 1e-3);
  EXPECT_NEAR(shading::svf_from_horizon(sigma), test::wall_svf(a, psi_l), 1e-3);
}

TEST(ExactHorizon, InfiniteWallLimit) {
  // Wall spanning the grid, receiver close to it: (1 + cos γ)/2 up to the grid ends.
  const int n = 201;
  const auto f = test::wall(n, 1.0, 20, 2, n / 2, 8.0);
  const int ir = 21 + 4;
  const double gamma = std::atan(8.0 / 4.0);
  const auto sigma = exact_horizons(f, ir, n / 2, 1440, flat_earth());
  // Rays within atan(4/100) of the wall's direction leave the grid first: ≤ 2e-3.
  EXPECT_NEAR(shading::skyview_from_horizon(sigma, {0, 0, 1}), (1 + std::cos(gamma)) / 2, 3e-3);
}

TEST(ExactHorizon, EarthCurvatureLowersDistantTerrain) {
  // 100 km at 1 km spacing: a flat plane sinks by t²/(2 R_eff); a ridge 60 km east
  // is seen at atan((H − d²/(2R_eff))/d).
  auto f = test::make_field(121, 3, 1000.0);
  ExactMarch m;  // curvature on by default
  const double r_eff = m.curvature.effective_radius();
  EXPECT_NEAR(r_eff, 6371000.0 / 0.87, 1e-6);
  const Heading east = heading_from_geographic(kPi / 2);
  const double step = exact_step_length(f, 1, east, 0.5);
  EXPECT_NEAR(exact_max_elevation(f, 0, 1, east, m), -std::atan(step / (2 * r_eff)), 1e-12);
  for (int j = 0; j < 3; ++j) f.at(60, j) = 400.0f;
  const double d = 60000.0;
  EXPECT_NEAR(exact_max_elevation(f, 0, 1, east, m), std::atan((400.0 - d * d / (2 * r_eff)) / d), 1e-12);
  EXPECT_NEAR(exact_max_elevation(f, 0, 1, east, flat_earth()), std::atan(400.0 / d), 1e-12);
}

TEST(ExactHorizon, MaxDistanceIsHonoured) {
  auto f = test::wall(65, 1.0, 10, 2, 32, 20.0);
  ExactMarch m = flat_earth();
  const Heading west = heading_from_geographic(1.5 * kPi);
  m.max_distance_m = 30.0;  // wall face at 40 m
  EXPECT_EQ(exact_max_elevation(f, 51, 32, west, m), 0.0);
  m.max_distance_m = 40.0;
  EXPECT_NEAR(exact_max_elevation(f, 51, 32, west, m), std::atan(20.0 / 40.0), 1e-12);
}

TEST(ExactHorizon, NoSampleOutsideTheGrid) {
  const auto f = test::make_field(8, 8, 1.0);
  EXPECT_TRUE(std::isinf(exact_max_elevation(f, 7, 3, heading_from_geographic(kPi / 2), flat_earth())));
}

}  // namespace
}  // namespace skylit::horizon
