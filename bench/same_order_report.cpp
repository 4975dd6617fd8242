// Prints, as markdown, the error the horizons alone put into `shaded` and `skyview`:
// the march and the sweep against exact horizons (the dense exact march) at the same W
// (32) and SH order (4), on the 256² synthetic scene and two projected real crops.
// `skylit bench` compares with an order-8 truth instead, which adds the order-4 band
// limit; there the march's bright bias (low horizons) partly cancels it
// (docs/quality-presets.md). Usage: same_order_report   (≈ 1 min on 2 cores)
#include "shading/products.h"
#include "shading/reference_pipeline.h"
#include "terrain/dem_reader.h"
#include "terrain/synthetic.h"

#include <cmath>
#include <cstdio>
#include <string>

using namespace skylit;
using namespace skylit::horizon;
using namespace skylit::shading;

namespace {

struct Stats {
  double rmse = 0.0, bias = 0.0;
};

Stats compare(const ProductBands& value, const ProductBands& truth) {
  Stats s;
  long n = 0;
  for (std::size_t i = 0; i < value.data.size(); ++i) {
    if (std::isnan(value.data[i]) || std::isnan(truth.data[i])) continue;
    const double d = static_cast<double>(value.data[i]) - truth.data[i];
    s.rmse += d * d, s.bias += d, ++n;
  }
  s.rmse = std::sqrt(s.rmse / n), s.bias /= n;
  return s;
}

void report(const char* name, const terrain::HeightField& f) {
  for (Product p : {Product::Shaded, Product::Skyview}) {
    ProductOptions exact;
    exact.exact = true;
    exact.exact_options.sky_azimuths = exact.march.azimuths;  // the same W as the others
    ProductOptions march, sweep;
    march.march.method = HorizonMethod::March;
    sweep.march.method = HorizonMethod::Sweep;
    const ProductBands truth = compute_product(f, p, exact);
    const Stats m = compare(compute_product(f, p, march), truth), s = compare(compute_product(f, p, sweep), truth);
    std::printf("| %s | %s | %.4f | %+.4f | %.4f | %+.4f |\n", name, std::string(product_name(p)).c_str(), m.rmse,
                m.bias, s.rmse, s.bias);
    std::fflush(stdout);
  }
}

}  // namespace

int main() {
  std::printf("| scene (256²) | product | march RMSE | march bias | sweep RMSE | sweep bias |\n");
  std::printf("| --- | --- | --- | --- | --- | --- |\n");
  terrain::SyntheticOptions so;
  so.width = so.height = 256;
  report("synthetic (bench scene)", terrain::make_synthetic_terrain(so));
  const std::string dir = std::string(SKYLIT_SHARED_DIR) + "/dem/";
  terrain::DemReadOptions ro;
  ro.window = terrain::PixelRect{450, 180, 256, 256};
  report("Big Tujunga 30 m, UTM", terrain::read_dem(dir + "big_tujunga_srtm30_utm11n.tif", ro).field);
  ro.window = terrain::PixelRect{100, 150, 256, 256};
  report("Similkameen 50 m, BC Albers", terrain::read_dem(dir + "similkameen_bc_50m_bcalbers.tif", ro).field);
  return 0;
}
