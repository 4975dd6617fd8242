// Trapezoid weights over uneven instants (time_integral.h) against closed forms: exact
// for linear functions, the exact error Σ h³/6 for t², and the second-order bound for
// cos; and the sun-hours gate against the DNI's own cut-off.
#include "shading/time_integral.h"

#include "shading/sky/sky_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace skylit::shading {
namespace {

// Uneven instants from 06:00Z: steps of 0.25, 1, 0.1, 0.75, 0.5 h, repeating.
std::vector<sky::UtcTime> uneven(int n) {
  const double steps_h[] = {0.5, 0.25, 1.0, 0.1, 0.75};
  std::vector<sky::UtcTime> t{sky::utc_from_civil(2026, 3, 20, 6)};
  for (int k = 1; k < n; ++k) t.push_back({t.back().unix_seconds + 3600.0 * steps_h[k % 5]});
  return t;
}

// Hours since the first instant.
double hours(const std::vector<sky::UtcTime>& t, std::size_t k) {
  return (t[k].unix_seconds - t[0].unix_seconds) / 3600.0;
}

TEST(TrapezoidWeights, SumToTheSpanAndIntegrateLinesExactly) {
  const auto t = uneven(23);
  const auto w = trapezoid_weights_hours(t);
  ASSERT_EQ(w.size(), t.size());
  double sum = 0, line = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    sum += w[k];
    line += w[k] * (3.0 - 2.0 * hours(t, k));
  }
  const double span = hours(t, t.size() - 1);
  EXPECT_NEAR(sum, span, 1e-12);
  EXPECT_NEAR(line, 3.0 * span - span * span, 1e-9);
}

TEST(TrapezoidWeights, QuadraticErrIsTheSumOfCubesOverSix) {
  // On [a, a + h], (h/2)(a² + (a+h)²) − ((a+h)³ − a³)/3 = h³/6.
  const auto t = uneven(31);
  const auto w = trapezoid_weights_hours(t);
  double got = 0, cubes = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    got += w[k] * hours(t, k) * hours(t, k);
    if (k > 0) cubes += std::pow(hours(t, k) - hours(t, k - 1), 3) / 6.0;
  }
  const double b = hours(t, t.size() - 1);
  EXPECT_NEAR(got - b * b * b / 3.0, cubes, 1e-9);
}

TEST(TrapezoidWeights, CosineWithinTheSecondOrderBound) {
  // |error| ≤ Σ h³/12 · max|f''| with f = cos(ωt), f'' ≤ ω²; closed form sin(ωb)/ω.
  const double omega = 2 * std::numbers::pi / 24.0;  // one cycle a day, per hour
  for (int n : {9, 33, 129}) {
    auto t = uneven(n);
    const auto w = trapezoid_weights_hours(t);
    double got = 0, bound = 0;
    for (std::size_t k = 0; k < t.size(); ++k) {
      got += w[k] * std::cos(omega * hours(t, k));
      if (k > 0) bound += std::pow(hours(t, k) - hours(t, k - 1), 3) / 12.0 * omega * omega;
    }
    const double exact = std::sin(omega * hours(t, t.size() - 1)) / omega;
    EXPECT_LE(std::abs(got - exact), bound) << n;
    EXPECT_GT(std::abs(got - exact), 0.05 * bound) << n;  // the bound is not vacuous
  }
}

TEST(TrapezoidWeights, OneInstantWeighsNothingAndOrderIsChecked) {
  const sky::UtcTime a{1000.0}, b{1000.0 + 1800.0};
  EXPECT_EQ(trapezoid_weights_hours(std::vector<sky::UtcTime>{a}), std::vector<double>{0.0});
  EXPECT_TRUE(trapezoid_weights_hours(std::vector<sky::UtcTime>{}).empty());
  EXPECT_EQ(trapezoid_weights_hours(std::vector<sky::UtcTime>{a, b}), (std::vector<double>{0.25, 0.25}));
  EXPECT_THROW(trapezoid_weights_hours(std::vector<sky::UtcTime>{b, a}), std::invalid_argument);
  EXPECT_THROW(trapezoid_weights_hours(std::vector<sky::UtcTime>{a, a}), std::invalid_argument);
}

TEST(SunHoursGate, CountsTheSunExactlyWhereItsBeamIsOn) {
  for (double e_deg : {-10.0, -0.2, 0.0, 0.001, 0.3, 45.0}) {
    const double e = e_deg * std::numbers::pi / 180.0;
    const sky::Sun s = sky::make_sun(sky::direction_from_azimuth_elevation(1.0, e), 3.0);
    EXPECT_EQ(sun_above_horizon(s), sky::luminance(s.dni) > 0.0) << e_deg;
    EXPECT_EQ(sun_above_horizon(s), e_deg > 0.0) << e_deg;
  }
}

}  // namespace
}  // namespace skylit::shading
