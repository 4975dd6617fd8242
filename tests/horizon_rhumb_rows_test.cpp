// The stretched row coordinate Γ of rhumb_rows.h against derivations that share none of
// its closed forms: Γ by composite Simpson quadrature of D_ref/D(y), its inverse by
// bisection, and the straight lines x = c + r·Γ(y) as curves of one metric heading
// (finite differences of east and north metres along them).
#include "shading/horizon/horizon_ray.h"
#include "shading/horizon/rhumb_rows.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace skylit::horizon {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Rows of dx ∝ cos φ from lat0 to lat1 (deg), dy 30 m.
terrain::HeightField rows_between(int h, double lat0, double lat1) {
  terrain::HeightField f(3, h, 30.0);
  for (int j = 0; j < h; ++j) f.dx_per_row[j] = 30.0 * std::cos((lat0 + (lat1 - lat0) * j / (h - 1)) * kDeg);
  return f;
}

double simpson_gamma(const terrain::HeightField& f, double y) {
  const int n = 20000;  // even
  const double d_ref = f.mean_dx(), h = y / n;
  auto g = [&](double t) { return d_ref / dx_at_row(f, t); };
  double sum = g(0.0) + g(y);
  for (int k = 1; k < n; ++k) sum += (k % 2 ? 4.0 : 2.0) * g(k * h);
  return sum * h / 3.0;
}

TEST(RhumbRows, GammaIsTheIntegralOfTheInverseSpacing) {
  // A 1° tile at 60° N, and rows spanning 20° to 85° N (spacings 11× apart: every segment
  // takes the log1p branch, not the series).
  for (auto [lat0, lat1] : {std::pair{60.0, 61.0}, {20.0, 85.0}}) {
    const terrain::HeightField f = rows_between(41, lat0, lat1);
    const RhumbRows rows(f);
    EXPECT_DOUBLE_EQ(rows.d_ref(), f.mean_dx());
    for (double y : {0.0, 0.25, 1.0, 7.5, 13.37, 29.9, 40.0}) {
      // Simpson's error on a kink-free segment is far below 1e-9 with 20000 panels; the
      // kinks at whole rows cost O(h²) of one panel.
      EXPECT_NEAR(rows.gamma(y), simpson_gamma(f, y), 1e-7 * (1.0 + y)) << lat0 << " y " << y;
      if (y == std::floor(y)) {
        EXPECT_EQ(rows.gamma(y), rows.half_rows()[static_cast<std::size_t>(2 * y)]);
      }
    }
    EXPECT_EQ(rows.half_rows().size(), 81u);
    EXPECT_EQ(rows.last(), rows.gamma(40.0));
    // Beyond the edges the spacing is the edge row's (dx_at_row clamps): linear.
    EXPECT_NEAR(rows.gamma(-2.0), -2.0 * rows.d_ref() / f.dx(0), 1e-12);
    EXPECT_NEAR(rows.gamma(43.0) - rows.last(), 3.0 * rows.d_ref() / f.dx(40), 1e-12);
  }
}

TEST(RhumbRows, RowInvertsGammaFromAnyHint) {
  for (auto [lat0, lat1] : {std::pair{60.0, 61.0}, {20.0, 85.0}}) {
    const RhumbRows rows(rows_between(41, lat0, lat1));
    for (double y = -3.0; y <= 43.0; y += 0.173) {
      const double g = rows.gamma(y);
      for (int hint : {0, 17, 39, 100, -5}) {
        int segment = hint;
        EXPECT_NEAR(rows.row(g, segment), y, 1e-10) << lat0 << " y " << y << " hint " << hint;
      }
      // Independent of the closed form: bisection on Simpson's Γ.
      if (y > 0.0 && y < 40.0 && std::fmod(y, 1.0) < 0.2) {
        double lo = 0.0, hi = 40.0;
        const terrain::HeightField f = rows_between(41, lat0, lat1);
        const double target = simpson_gamma(f, y);
        for (int k = 0; k < 60; ++k) (simpson_gamma(f, 0.5 * (lo + hi)) < target ? lo : hi) = 0.5 * (lo + hi);
        int segment = 0;
        EXPECT_NEAR(rows.row(target, segment), 0.5 * (lo + hi), 1e-7) << y;
      }
    }
  }
}

TEST(RhumbRows, StraightLinesInGammaKeepOneMetricHeading) {
  // Rows from 55° to 75° N: the east step per row changes 2.3× along a line.
  const terrain::HeightField f = rows_between(201, 55.0, 75.0);
  const RhumbRows rows(f);
  for (double az_deg : {10.0, 35.0, 60.0, 120.0, 200.0, 300.0}) {
    const double e = std::sin(az_deg * kDeg), n = std::cos(az_deg * kDeg);
    const double r = -e * f.dy / (n * rows.d_ref());  // x = c + r·Γ(y)
    // East metres per texel step east come from the spacing at the step's mid-row.
    for (double y = 5.0; y < 195.0; y += 9.7) {
      const double h = n > 0.0 ? -1e-3 : 1e-3;  // rows grow south: step along the heading
      const double x0 = 3.0 + r * rows.gamma(y - h), x1 = 3.0 + r * rows.gamma(y + h);
      const double east = (x1 - x0) * dx_at_row(f, y), north = -(2.0 * h) * f.dy;
      EXPECT_NEAR(std::atan2(east, north), std::atan2(e, n), 1e-7) << az_deg << " y " << y;
    }
  }
}

}  // namespace
}  // namespace skylit::horizon
