// gdaldem's hillshade on tilted planes against the closed form: 1 + 254·max(n·l, 0),
// n the plane's unit normal, l the unit vector towards the light.
#include "shading/relief/gdal_hillshade.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace skylit::relief {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Plane h = gx·east + gy·north on a w×h grid with spacings dx, dy (row j grows south).
terrain::HeightField plane(double gx, double gy, double dx, double dy) {
  terrain::HeightField f(9, 7, dx);
  f.dy = dy;
  for (int j = 0; j < f.height; ++j)
    for (int i = 0; i < f.width; ++i) f.at(i, j) = static_cast<float>(gx * i * dx - gy * j * dy + 0.25);
  return f;
}

double closed_form(double gx, double gy, double z, double az_deg, double alt_deg) {
  const double nx = -gx * z, ny = -gy * z, norm = std::sqrt(1 + nx * nx + ny * ny);
  const double lx = std::sin(az_deg * kDeg) * std::cos(alt_deg * kDeg);
  const double ly = std::cos(az_deg * kDeg) * std::cos(alt_deg * kDeg);
  const double c = (nx * lx + ny * ly + std::sin(alt_deg * kDeg)) / norm;
  return 1 + 254 * std::max(c, 0.0);
}

TEST(GdalHillshade, TiltedPlanesMatchTheClosedForm) {
  struct Case { double gx, gy, dx, dy, z, az, alt; Gradient g; };
  for (const Case& c : {Case{0.3, -0.2, 30, 30, 1, 315, 45, Gradient::Horn},       // same-resolution shortcut
                        Case{0.3, -0.2, 30, 20, 1, 315, 45, Gradient::Horn},       // general path
                        Case{-0.5, 0.1, 10, 12, 2.5, 200, 30, Gradient::ZevenbergenThorne},
                        Case{1.5, 0.0, 5, 5, 1, 90, 20, Gradient::Horn}}) {        // facing away: 1
    HillshadeOptions o;
    o.gradient = c.g;
    o.z = c.z;
    o.azimuth_deg = c.az;
    o.altitude_deg = c.alt;
    const auto f = plane(c.gx, c.gy, c.dx, c.dy);
    const auto v = gdal_hillshade(f, o);
    const double want = closed_form(c.gx, c.gy, c.z, c.az, c.alt);
    for (int j = 0; j < f.height; ++j)
      for (int i = 0; i < f.width; ++i) {
        const float got = v[static_cast<std::size_t>(j) * f.width + i];
        const bool border = i == 0 || j == 0 || i == f.width - 1 || j == f.height - 1;
        if (border) EXPECT_TRUE(std::isnan(got)) << i << "," << j;  // gdaldem leaves edges nodata
        else EXPECT_NEAR(got, want, 2e-3) << c.gx << " " << c.dy << " at " << i << "," << j;
      }
    // 2a − b extends a plane exactly; gdaldem's corners repeat their own column instead
    // (its top and bottom rows clamp the column index), so they are left out.
    o.compute_edges = true;
    const auto e = gdal_hillshade(f, o);
    for (int j = 0; j < f.height; ++j)
      for (int i = 0; i < f.width; ++i)
        if ((i != 0 && i != f.width - 1) || (j != 0 && j != f.height - 1)) {
          EXPECT_NEAR(e[static_cast<std::size_t>(j) * f.width + i], want, 2e-3) << "edge " << i << "," << j;
        }
  }
}

TEST(GdalHillshade, NodataCentreAndNeighbours) {
  auto f = plane(0.2, 0.1, 10, 10);
  f.valid[3 * f.width + 4] = 0;
  HillshadeOptions o;
  const auto v = gdal_hillshade(f, o);
  for (int j = 2; j <= 4; ++j)
    for (int i = 3; i <= 5; ++i) EXPECT_TRUE(std::isnan(v[j * f.width + i])) << i << "," << j;
  o.compute_edges = true;  // neighbours take the centre's value instead: finite, centre still nodata
  const auto e = gdal_hillshade(f, o);
  EXPECT_TRUE(std::isnan(e[3 * f.width + 4]));
  EXPECT_FALSE(std::isnan(e[2 * f.width + 3]));
}

}  // namespace
}  // namespace skylit::relief
