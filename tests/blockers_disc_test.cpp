// The sun disc behind spheres (shading/blockers/disc_occlusion.h): the cap–cap
// intersection area against Monte Carlo on the sphere and against closed forms (two
// hemispheres: a lune; nested caps); the analytic disc fraction against disc sampling
// for one sphere at the disc's edge, for overlapping spheres, and on hard cases.
#include "shading/blockers/disc_occlusion.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace skylit::blockers {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kSun = 0.004654;  // the sun's angular radius (rad)

double monte_carlo_overlap(double a, double b, double c, int samples) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> g;
  const glm::dvec3 u(0, 0, 1), v(std::sin(c), 0, std::cos(c));
  int both = 0;
  for (int k = 0; k < samples; ++k) {
    const glm::dvec3 w = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
    both += glm::dot(w, u) >= std::cos(a) && glm::dot(w, v) >= std::cos(b);
  }
  return 4.0 * kPi * both / samples;
}

TEST(CapIntersection, ClosedFormsAndLimits) {
  // Two hemispheres whose poles are c apart meet in a lune of angle π − c: 2(π − c).
  for (double c : {0.1, 1.0, 2.5}) EXPECT_NEAR(cap_intersection_area(kPi / 2, kPi / 2, c), 2 * (kPi - c), 1e-12);
  EXPECT_NEAR(cap_intersection_area(0.3, 0.1, 0.05), 2 * kPi * (1 - std::cos(0.1)), 1e-15);  // nested
  EXPECT_EQ(cap_intersection_area(0.3, 0.1, 0.41), 0.0);                                    // apart
}

TEST(CapIntersection, AgreesWithMonteCarlo) {
  const int n = 4'000'000;
  for (const auto& [a, b, c] : {std::array{0.5, 0.4, 0.6}, std::array{1.2, 0.3, 1.1}, std::array{1.5, 1.5, 0.4}}) {
    const double mc = monte_carlo_overlap(a, b, c, n);
    const double sigma = std::sqrt(mc * (4 * kPi - mc) / n);  // binomial standard error (sr)
    EXPECT_NEAR(cap_intersection_area(a, b, c), mc, 5 * sigma) << a << " " << b << " " << c;
  }
}

// Planar lens: the area two discs of radii r, R with centres d apart share.
double lens_area(double r, double R, double d) {
  const double k = std::sqrt((-d + r + R) * (d + r - R) * (d - r + R) * (d + r + R));
  return r * r * std::acos((d * d + r * r - R * R) / (2 * d * r)) +
         R * R * std::acos((d * d + R * R - r * r) / (2 * d * R)) - 0.5 * k;
}

TEST(CapIntersection, SunSizedCapsMatchThePlanarLens) {
  // For caps a few sun radii wide the sphere is flat to O(angle²) ≈ 1e-4: the spherical
  // formula, whose terms are of order π, must keep the digits of an area of ~7e-5 sr.
  for (const auto& [b, c] : {std::array{0.01, 0.011}, std::array{0.005, 0.003}, std::array{0.02, 0.0175}}) {
    const double lens = lens_area(kSun, b, c);
    EXPECT_NEAR(cap_intersection_area(kSun, b, c), lens, 3e-4 * lens) << b << " " << c;
  }
}

TEST(DiscFraction, OneSphereMatchesSamplingAcrossThePenumbra) {
  const glm::dvec3 p(0, 0, 0), sun = glm::normalize(glm::dvec3(0.3, 0.2, 1.0));
  const std::vector<std::uint32_t> all{0};
  glm::dvec3 side = glm::normalize(glm::cross(sun, glm::dvec3(1, 0, 0)));
  const double dist = 300.0, r = 2.0, edge = std::asin(r / dist);
  for (double off : {-2.0, -0.5, 0.0, 0.3, 0.9, 2.0}) {
    // Centre offset so the cap edge crosses the disc at `off` disc radii from its centre.
    const double angle = edge + off * kSun;
    const glm::dvec3 dir = std::cos(angle) * sun + std::sin(angle) * side;
    const std::vector<Sphere> s{{p + dist * dir, r}};
    const double analytic = disc_fraction_left(s, all, p, sun, kSun);
    const double sampled = disc_fraction_sampled(s, p, sun, kSun, 20000);
    EXPECT_NEAR(analytic, sampled, 2e-3) << off;
  }
}

TEST(DiscFraction, OverlappingSpheresStayNearTheUnion) {
  // Three spheres over the disc, overlapping one another: the product of shares against
  // the sampled union, within the overlap's share.
  const glm::dvec3 p(0, 0, 0), sun(0, 0, 1);
  const double d = 500.0;
  const std::vector<Sphere> s{{{0.6, 0.0, d}, 1.5}, {{-0.4, 0.8, d}, 1.2}, {{0.1, -0.9, d}, 1.0}};
  const std::vector<std::uint32_t> all{0, 1, 2};
  const double analytic = disc_fraction_left(s, all, p, sun, kSun);
  const double sampled = disc_fraction_sampled(s, p, sun, kSun, 40000);
  EXPECT_NEAR(analytic, sampled, 0.03);
  EXPECT_GE(analytic, 0.0);
}

TEST(DiscFraction, HardCasesStayFinite) {
  const glm::dvec3 p(0, 0, 0), sun(0, 0, 1);
  std::vector<Sphere> coincident(400, Sphere{{0, 0, 100}, 0.2});
  std::vector<std::uint32_t> idx(400);
  for (std::uint32_t k = 0; k < 400; ++k) idx[k] = k;
  const double f = disc_fraction_left(coincident, idx, p, sun, kSun);
  EXPECT_TRUE(std::isfinite(f));
  EXPECT_GE(f, 0.0);
  EXPECT_NEAR(f, disc_fraction_sampled(coincident, p, sun, kSun, 4096), 0.05);  // the disc is covered: 0
  const std::vector<std::uint32_t> one{0};
  // A 1 mm sphere at 10 km, the receiver inside a sphere, a sphere at the receiver.
  EXPECT_NEAR(disc_fraction_left(std::vector<Sphere>{{{0, 0, 10000}, 0.001}}, one, p, sun, kSun), 1.0, 1e-9);
  EXPECT_EQ(disc_fraction_left(std::vector<Sphere>{{{0, 0, 0.5}, 1.0}}, one, p, sun, kSun), 0.0);
  EXPECT_EQ(disc_fraction_left(std::vector<Sphere>{{{0, 0, 0}, 1.0}}, one, p, sun, kSun), 0.0);
}

}  // namespace
}  // namespace skylit::blockers
