// Products on a geographic grid (rows of several spacings, rhumb-line sweep) against a
// closed form: a paraboloid crater at 60° N on a 3″ grid (dx = 46 m, dy = 93 m), whose
// centre sees the rim at the same elevation in every direction, Earth curvature
// included. Default settings, as `skylit shade` runs them, must come within 0.01 of
// the closed-form svf; the same crater on a grid of one spacing is the yardstick.
#include "terrain_test_util.h"

#include "shading/horizon/horizon_ray.h"
#include "shading/horizon/horizon_sweep.h"
#include "shading/products.h"
#include "shading/reference_pipeline.h"

#include "terrain/dem_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <numbers>
#include <vector>

namespace skylit::shading {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kRadius = 2000.0, kDepth = 400.0;  // crater rim radius and depth (m)

// z = depth·((r/R)² − 1) inside the rim, 0 outside; (x, y) metric offsets of each texel
// from the centre along its own row's spacing.
terrain::HeightField crater(int w, int h, double dy, const std::vector<double>& dx) {
  terrain::HeightField f(w, h, dy);
  f.dx_per_row = dx;
  const double ci = 0.5 * (w - 1), cj = 0.5 * (h - 1);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const double r = std::hypot((i - ci) * dx[j], (cj - j) * dy);
      f.at(i, j) = static_cast<float>(r < kRadius ? kDepth * ((r / kRadius) * (r / kRadius) - 1.0) : 0.0);
    }
  return f;
}

// The centre's horizon: max over r of (z(r) − z(0) − r²/(2R_eff))/r rises to the rim.
double closed_form_svf(const ProductOptions& o) {
  const double tan_theta = kDepth / kRadius - kRadius * o.march.curvature.drop_per_square_metre();
  return svf_from_horizon(std::vector<double>(o.march.azimuths, std::atan(tan_theta)));
}

TEST(GeographicProducts, CraterAt60NorthMeetsItsClosedFormAtDefaultSettings) {
  const int w = 121, h = 61;
  const double dy = 92.66;  // 3″ of latitude
  std::vector<double> geographic(h), projected;
  for (int j = 0; j < h; ++j) {
    const double lat = (60.0 + (0.5 * (h - 1) - j) * 3.0 / 3600.0) * kDeg;
    geographic[j] = 6378137.0 * std::cos(lat) * (3.0 / 3600.0) * kDeg;  // 46.4 m
  }
  const terrain::HeightField geo = crater(w, h, dy, geographic);
  ASSERT_FALSE(horizon::one_row_spacing(geo));
  projected.assign(h, geo.mean_dx());
  const terrain::HeightField flat_rows = crater(w, h, dy, projected);

  const ProductOptions o;  // the defaults: the sweep
  ASSERT_TRUE(uses_sweep(geo, o));
  const double truth = closed_form_svf(o);
  const int ci = w / 2, cj = h / 2;
  const double svf_geo = compute_product(geo, Product::Svf, o).at(0, ci, cj);
  const double svf_projected = compute_product(flat_rows, Product::Svf, o).at(0, ci, cj);
  ProductOptions march = o;
  march.march.method = horizon::HorizonMethod::March;
  const double svf_march = compute_product(geo, Product::Svf, march).at(0, ci, cj);
  std::printf("crater centre svf: closed form %.4f, sweep %.4f geographic, %.4f one spacing, march %.4f\n", truth,
              svf_geo, svf_projected, svf_march);
  EXPECT_NEAR(svf_geo, truth, 0.01);
  EXPECT_NEAR(svf_geo, svf_projected, 0.002);
}

// RMSE of a band-0 product against --exact over the valid texels.
double rmse_against_exact(const terrain::HeightField& f, Product p) {
  ProductOptions exact;
  exact.exact = true;
  const ProductBands a = compute_product(f, p, ProductOptions{}), b = compute_product(f, p, exact);
  double sum = 0.0;
  long n = 0;
  for (std::size_t t = 0; t < f.size(); ++t)
    if (f.valid[t]) sum += std::pow(a.data[t] - b.data[t], 2), ++n;
  return std::sqrt(sum / n);
}

// Real SRTM on its geographic grid against the same heights on one row spacing (a
// projected twin: the sweep's straight lines): the default svf and skyview errors
// against the exact march agree within 10 %. (A UTM reprojection would resample, and
// smoother heights are easier for every method: docs/accuracy.md.)
TEST(GeographicProducts, RealDemHasTheErrorOfItsProjectedTwin) {
  const std::string dem = std::string(SKYLIT_SHARED_DIR) + "/dem/franconia_hills_srtm3_4326.tif";
  SKYLIT_REQUIRE(terrain::testing::missing_file(dem));
  terrain::DemReadOptions read;
  read.window = terrain::PixelRect{300, 300, 72, 72};  // the exact march costs N³
  const terrain::HeightField geo = terrain::read_dem(dem, read).field;
  ASSERT_FALSE(horizon::one_row_spacing(geo));
  terrain::HeightField twin = geo;
  twin.dx_per_row.assign(twin.height, geo.mean_dx());
  for (Product p : {Product::Svf, Product::Skyview}) {
    const double e_geo = rmse_against_exact(geo, p), e_twin = rmse_against_exact(twin, p);
    std::printf("%s RMSE against --exact: %.5f geographic, %.5f projected twin\n", product_name(p).data(), e_geo,
                e_twin);
    EXPECT_LT(e_geo, 1.1 * e_twin) << product_name(p);
    EXPECT_GT(e_geo, 0.0);
  }
}

}  // namespace
}  // namespace skylit::shading
