// Visible fraction of the solar disc and of rectangular key lights (sun_disc.h) against
// brute force: dense grids over the disc (or the light) with a per-sample horizon test
// on the sphere, independent of the tangent-plane frame and of the closed forms.
#include "shading/sky/sun_disc.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

namespace skylit::sky {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;
const double kR = sky::kSunAngularRadius;

// Fraction of grid points p (N×N cell centres over [−1, 1]², inside the unit disc)
// with visible(p).
double grid_fraction(int n, const std::function<bool(double, double)>& visible) {
  long inside = 0, lit = 0;
  for (int b = 0; b < n; ++b)
    for (int a = 0; a < n; ++a) {
      const double x = -1.0 + (a + 0.5) * 2.0 / n, y = -1.0 + (b + 0.5) * 2.0 / n;
      if (x * x + y * y >= 1.0) continue;
      ++inside;
      lit += visible(x, y);
    }
  return static_cast<double>(lit) / inside;
}

// Directions over the solar disc on the sphere (disc of angular radius ≈ r around the
// sun at geographic azimuth az, elevation el), classified by `visible(direction)`.
double sphere_fraction(double az, double el, double r, int n, const std::function<bool(const glm::dvec3&)>& visible) {
  const glm::dvec3 s{std::cos(el) * std::sin(az), std::cos(el) * std::cos(az), std::sin(el)};
  // Any orthonormal pair perpendicular to s: the sampling must not share the
  // azimuth/elevation frame of the code under test.
  const glm::dvec3 helper = std::abs(s.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  const glm::dvec3 u = glm::normalize(glm::cross(s, helper)), v = glm::cross(s, u);
  return grid_fraction(n, [&](double x, double y) { return visible(glm::normalize(s + r * (x * u + y * v))); });
}

double wrap_pi(double a) { return std::remainder(a, 2.0 * kPi); }

// Per-sample test against the horizon e = σ + k·(A − A_s).
double brute_sun(double az, double el, double sigma, double k, int n = 500) {
  return sphere_fraction(az, el, kR, n, [&](const glm::dvec3& w) {
    const double a = std::atan2(w.x, w.y), e = std::asin(std::clamp(w.z, -1.0, 1.0));
    return e > sigma + k * wrap_pi(a - az);
  });
}

TEST(DiscLine, ClosedFormMatchesGridAndKnownValues) {
  EXPECT_DOUBLE_EQ(disc_fraction_above_line(1.0), 1.0);
  EXPECT_DOUBLE_EQ(disc_fraction_above_line(3.0), 1.0);
  EXPECT_DOUBLE_EQ(disc_fraction_above_line(-1.0), 0.0);
  EXPECT_NEAR(disc_fraction_above_line(0.0), 0.5, 1e-15);
  for (double u : {-0.9, -0.5, -0.2, 0.1, 0.3, 0.77}) {
    // Symmetry: the two sides of a line share the disc.
    EXPECT_NEAR(disc_fraction_above_line(u) + disc_fraction_above_line(-u), 1.0, 1e-14);
    EXPECT_NEAR(disc_fraction_above_line(u), grid_fraction(1200, [&](double, double y) { return y + u > 0; }), 1.5e-3)
        << u;
  }
}

TEST(DiscLine, ClippedPolygonEqualsClosedFormForOneLineAtAnyAngle) {
  for (double angle : {0.0, 0.3, 1.2, 2.5, -2.0})
    for (double u : {-1.3, -0.8, -0.1, 0.0, 0.45, 0.99, 1.2}) {
      const DiscLine l{std::cos(angle), std::sin(angle), u};
      EXPECT_NEAR(disc_fraction_above_lines({&l, 1}), disc_fraction_above_line(u), 1e-12) << angle << " " << u;
    }
}

TEST(DiscLine, TwoAndThreeLinesMatchGrid) {
  struct Case {
    std::vector<DiscLine> lines;
  };
  auto line = [](double angle, double offset) { return DiscLine{std::cos(angle), std::sin(angle), offset}; };
  const std::vector<Case> cases = {
      {{line(1.2, 0.1), line(2.4, 0.3)}},     // corner inside the disc
      {{line(0.0, 0.5), line(0.1, -0.2)}},    // nearly parallel
      {{line(0.0, 0.3), line(kPi, 0.3)}},     // a strip
      {{line(0.0, -0.3), line(kPi, -0.3)}},   // disjoint half-planes: nothing visible
      {{line(0.5, 2.0), line(1.5, -0.4)}},    // one line misses the disc
      {{line(0.2, 0.6), line(2.3, 0.1), line(4.4, 0.5)}},  // a triangle-ish cut
  };
  for (const Case& c : cases) {
    const double expected = grid_fraction(1200, [&](double x, double y) {
      for (const DiscLine& l : c.lines)
        if (l.nx * x + l.ny * y + l.offset <= 0) return false;
      return true;
    });
    EXPECT_NEAR(disc_fraction_above_lines(c.lines), expected, 1.5e-3);
  }
}

TEST(DiscLine, PolylineMatchesGridForKinkedAndJumpingHorizons) {
  const std::vector<double> x = {-1.2, -0.3, 0.2, 0.2, 1.0};
  const std::vector<double> y = {-0.5, 0.4, -0.1, 0.6, 0.2};  // kink, then a jump at x = 0.2
  auto height = [&](double px) {
    for (std::size_t k = 0; k + 1 < x.size(); ++k)
      if (px >= x[k] && px < x[k + 1]) return y[k] + (y[k + 1] - y[k]) * (px - x[k]) / (x[k + 1] - x[k]);
    return y.back();
  };
  const DiscLine tangent{0.6, 0.8, 0.7};
  EXPECT_NEAR(disc_fraction_above_polyline(x, y), grid_fraction(1200, [&](double px, double py) { return py > height(px); }),
              1.5e-3);
  EXPECT_NEAR(disc_fraction_above_polyline(x, y, &tangent), grid_fraction(1200, [&](double px, double py) {
                return py > height(px) && tangent.nx * px + tangent.ny * py + tangent.offset > 0;
              }),
              1.5e-3);
  // A straight polyline is the single line.
  const std::vector<double> x2 = {-1.0, 1.0}, y2 = {-0.4, 0.2};
  const DiscLine l = horizon_line(0.0, -0.1 * kR, 0.3, kR);  // y = −0.1 + 0.3x
  const std::vector<double> y3 = {-0.4, 0.2};
  EXPECT_NEAR(disc_fraction_above_polyline(x2, y3), disc_fraction_above_line(0.1 / std::sqrt(1.09)), 1e-12);
  EXPECT_NEAR(disc_fraction_above_lines({&l, 1}), disc_fraction_above_line(0.1 / std::sqrt(1.09)), 1e-12);
  EXPECT_THROW(disc_fraction_above_polyline(std::vector<double>{-0.5, 1.0}, y2), std::invalid_argument);
}

TEST(SunDisc, LimitsFullLitShadowHalfZenithBelowHorizon) {
  const double e = 10 * kDeg;
  EXPECT_DOUBLE_EQ(sun_disc_fraction(e, e - 1.01 * kR), 1.0);
  EXPECT_DOUBLE_EQ(sun_disc_fraction(e, e + 1.01 * kR), 0.0);
  for (double k : {0.0, 0.4, -3.0}) EXPECT_NEAR(sun_disc_fraction(e, e, k), 0.5, 1e-15);
  // Zenith: the disc spans ±1 rad of azimuth in the frame (cos e_s floored at sin r), so
  // it stays lit while the line continued that far stays below it: |k| < π/2 − σ − r.
  for (double k : {0.0, 0.3, -0.45}) EXPECT_DOUBLE_EQ(sun_disc_fraction(kPi / 2, 60 * kDeg, k), 1.0);
  EXPECT_NEAR(sun_disc_fraction(kPi / 2, 60 * kDeg, 0.0), brute_sun(0.3, kPi / 2, 60 * kDeg, 0.0, 200), 0.0);
  // Sun below the horizon.
  EXPECT_DOUBLE_EQ(sun_disc_fraction(-1 * kDeg, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(brute_sun(1.0, -1 * kDeg, 0.0, 0.0, 200), 0.0);
  // Penumbra: the visible fraction grows monotonically over e_s ∈ [σ − r, σ + r].
  double prev = -1.0;
  for (int s = -10; s <= 10; ++s) {
    const double f = sun_disc_fraction(e + s * kR / 10, e, 0.2);
    EXPECT_GE(f, prev);
    prev = f;
  }
}

TEST(SunDisc, ClosedFormMatchesSphereSamplingWithTiltedHorizons) {
  for (double el : {2 * kDeg, 10 * kDeg, 35 * kDeg, 70 * kDeg})
    for (double dsig : {-0.8, -0.35, 0.0, 0.5})
      for (double k : {0.0, 0.25, -1.0, 3.0}) {
        const double az = 1.7, sigma = el + dsig * kR;
        const double brute = brute_sun(az, el, sigma, k);
        // Tangent-plane frame: O(r²) in general; at 70° the azimuth lines converge
        // across the disc (cos e changes by r·tan e ≈ 1.3%), bending a steep line.
        const double tol = el > 60 * kDeg && k != 0.0 ? 1e-2 : 3e-3;
        EXPECT_NEAR(sun_disc_fraction(el, sigma, k), brute, tol) << el / kDeg << " " << dsig << " " << k;
      }
}

TEST(SunDisc, TangentPlaneLineMatchesSphereSamplingAtTheTerminator) {
  const glm::dvec3 n = glm::normalize(glm::dvec3(-0.5, 0.2, 1.0));
  for (double az : {0.4, 1.9, 4.0}) {
    // Elevation where the sun's centre sits on the plane: n·s = 0.
    const double a = n.x * std::sin(az) + n.y * std::cos(az);
    const double e0 = std::atan2(-a, n.z);
    for (double de : {-1.2, -0.6, 0.0, 0.3, 0.9}) {
      const double el = e0 + de * kR;
      const DiscLine l = tangent_plane_line(n, az, el);
      const double brute = sphere_fraction(az, el, kR, 800, [&](const glm::dvec3& w) { return glm::dot(n, w) > 0; });
      EXPECT_NEAR(disc_fraction_above_lines({&l, 1}), brute, 3e-3) << az << " " << de;
    }
  }
  // Sun at the plane's pole: fully visible, no line crosses the disc.
  const glm::dvec3 up{0, 0, 1};
  const DiscLine pole = tangent_plane_line(up, 0.0, kPi / 2);
  EXPECT_DOUBLE_EQ(disc_fraction_above_lines({&pole, 1}), 1.0);
}

// Brute force over a rectangular light: midpoint grid in (A, e) with weight cos e.
double brute_rect(const RectLight& l, const std::function<double(double)>& horizon, int n = 1500) {
  double lit = 0.0, total = 0.0;
  for (int a = 0; a < n; ++a) {
    const double az = l.azimuth_min + (a + 0.5) * (l.azimuth_max - l.azimuth_min) / n;
    const double h = horizon(az);
    for (int b = 0; b < n; ++b) {
      const double e = l.elevation_min + (b + 0.5) * (l.elevation_max - l.elevation_min) / n;
      total += std::cos(e);
      if (e > h) lit += std::cos(e);
    }
  }
  return lit / total;
}

TEST(RectLight, LinearHorizonMatchesBruteForce) {
  const RectLight l{1.0, 1.6, 5 * kDeg, 40 * kDeg};
  const double centre = 1.3;
  struct Case {
    double sigma, slope;
  };
  for (const Case c : {Case{20 * kDeg, 0.0}, Case{20 * kDeg, 1.2}, Case{10 * kDeg, -0.9}, Case{0.0, 0.0},
                       Case{50 * kDeg, 0.0}, Case{30 * kDeg, 2.5}}) {
    const double expected = brute_rect(l, [&](double a) { return c.sigma + c.slope * (a - centre); });
    EXPECT_NEAR(rect_light_fraction(l, c.sigma, c.slope), expected, 2e-3) << c.sigma << " " << c.slope;
  }
  EXPECT_DOUBLE_EQ(rect_light_fraction(l, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(rect_light_fraction(l, 41 * kDeg), 0.0);
  // Below the horizontal too (elevations down to −π/2 are allowed).
  const RectLight low{0.0, 0.5, -30 * kDeg, 10 * kDeg};
  EXPECT_NEAR(rect_light_fraction(low, -5 * kDeg, 0.7),
              brute_rect(low, [&](double a) { return -5 * kDeg + 0.7 * (a - 0.25); }), 2e-3);
}

TEST(RectLight, PiecewiseHorizonMatchesBruteForce) {
  const RectLight l{0.2, 1.4, 0.0, 35 * kDeg};
  // Samples beyond both ends, a kink, and a jump at 0.9 (repeated azimuth).
  const std::vector<double> az = {0.0, 0.5, 0.9, 0.9, 1.2, 2.0};
  const std::vector<double> sg = {5 * kDeg, 25 * kDeg, 12 * kDeg, 30 * kDeg, 8 * kDeg, 20 * kDeg};
  auto horizon = [&](double a) {
    for (std::size_t k = 0; k + 1 < az.size(); ++k)
      if (a >= az[k] && a < az[k + 1]) return sg[k] + (sg[k + 1] - sg[k]) * (a - az[k]) / (az[k + 1] - az[k]);
    return sg.back();
  };
  EXPECT_NEAR(rect_light_fraction(l, az, sg), brute_rect(l, horizon), 2e-3);
  // Samples that start inside the light: constant extension to its edges.
  const std::vector<double> az2 = {0.6, 1.0}, sg2 = {10 * kDeg, 20 * kDeg};
  EXPECT_NEAR(rect_light_fraction(l, az2, sg2), brute_rect(l, [&](double a) {
                return a <= 0.6 ? 10 * kDeg : a >= 1.0 ? 20 * kDeg : 10 * kDeg + (a - 0.6) * 25 * kDeg;
              }),
              2e-3);
  // One sample = constant horizon = the linear form with slope 0.
  const std::vector<double> one_az = {0.7}, one_sg = {15 * kDeg};
  EXPECT_NEAR(rect_light_fraction(l, one_az, one_sg), rect_light_fraction(l, 15 * kDeg), 1e-14);
}

TEST(RectLight, ValidationAndSunLikeLimit) {
  EXPECT_THROW(rect_light_fraction(RectLight{1.0, 1.0, 0.0, 0.1}, 0.0), std::invalid_argument);
  EXPECT_THROW(rect_light_fraction(RectLight{0.0, 1.0, 0.2, 0.1}, 0.0), std::invalid_argument);
  EXPECT_THROW(rect_light_fraction(RectLight{0.0, 1.0, -2.0, 0.1}, 0.0), std::invalid_argument);
  EXPECT_THROW(sun_disc_fraction(0.1, 0.0, 0.0, 0.0), std::invalid_argument);
  // A square light of the sun's size, horizon through its centre: the upper half of
  // the solid angle, (sin(e+r) − sin e)/(sin(e+r) − sin(e−r)).
  const double e = 10 * kDeg;
  const RectLight sq{1.0 - kR, 1.0 + kR, e - kR, e + kR};
  EXPECT_NEAR(rect_light_fraction(sq, e), (std::sin(e + kR) - std::sin(e)) / (std::sin(e + kR) - std::sin(e - kR)),
              1e-12);
}

}  // namespace
}  // namespace skylit::sky
