// Prints, as markdown, the accuracy of the multi-resolution horizon march (NS09's and
// ours, with parameter variants) and of the horizon sweep (the default where it applies:
// the projected crops) against the exact ground truth (dense half-texel march, 360
// azimuths) for the svf and skyview products on crops of real DEMs in shared/dem.
// Usage: accuracy_report [stride]  (truth at every stride-th texel, default 2).
#include "parallel/parallel_rows.h"
#include "shading/horizon/azimuth.h"
#include "shading/horizon/horizon_exact.h"
#include "shading/horizon/horizon_sweep.h"
#include "shading/horizon/surface_normals.h"
#include "shading/products.h"
#include "shading/reference_pipeline.h"
#include "terrain/dem_reader.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

using namespace skylit;
using namespace skylit::horizon;
using namespace skylit::shading;

namespace {

struct Crop {
  const char* file;
  terrain::PixelRect window;
  const char* what;
};

// Deep valleys and canyons, projected and geographic, a few hundred texels square.
const Crop kCrops[] = {
    {"similkameen_bc_50m_bcalbers.tif", {100, 150, 256, 256}, "valley walls, 50 m, BC Albers"},
    {"big_tujunga_srtm30_utm11n.tif", {450, 180, 256, 256}, "canyon, 30 m, UTM 11N"},
    {"pyrenees_andorra_srtm3_4326.tif", {450, 450, 224, 224}, "alpine, 3″ geographic (per-row dx)"},
};

constexpr int kTruthAzimuths = 360;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct Truth {
  std::vector<int> ii, jj;                   // texels where truth is known
  std::vector<double> svf, skyview;          // 360 azimuths
  std::vector<double> svf_w, skyview_w;      // the product's W azimuths, exact horizons
  std::vector<double> horizon_deg;           // exact horizon product, W bands per texel
};

Truth ground_truth(const terrain::HeightField& f, int stride, int w) {
  Truth t;
  for (int j = 0; j < f.height; j += stride)
    for (int i = 0; i < f.width; i += stride)
      if (f.is_valid(i, j)) t.ii.push_back(i), t.jj.push_back(j);
  const std::size_t n = t.ii.size();
  t.svf.resize(n), t.skyview.resize(n), t.svf_w.resize(n), t.skyview_w.resize(n);
  t.horizon_deg.resize(n * w);
  const ExactMarch exact;  // curvature on, DEM extent, half-texel steps
  parallel::parallel_rows(static_cast<int>(n), 0, [&](int k) {
    const int i = t.ii[k], j = t.jj[k];
    const glm::dvec3 nrm = horn_normal(f, i, j);
    for (int az : {kTruthAzimuths, w}) {
      std::vector<double> sigma(az);
      for (int b = 0; b < az; ++b)
        sigma[b] = exact_max_elevation(f, i, j, heading_from_geographic(band_azimuth(b, az)), exact);
      if (az == w)
        for (int b = 0; b < w; ++b) t.horizon_deg[k * w + b] = std::max(sigma[b], 0.0) * 180.0 / 3.14159265358979323846;
      (az == w ? t.svf_w : t.svf)[k] = svf_from_horizon(sigma);
      (az == w ? t.skyview_w : t.skyview)[k] = skyview_from_horizon(sigma, nrm);
    }
  });
  return t;
}

struct Stats {
  double rmse = 0, max_abs = 0, bias = 0;
};

template <typename Get>
Stats compare(const std::vector<double>& truth, Get&& get) {
  Stats s;
  for (std::size_t k = 0; k < truth.size(); ++k) {
    const double e = get(k) - truth[k];
    s.rmse += e * e, s.bias += e, s.max_abs = std::max(s.max_abs, std::abs(e));
  }
  s.rmse = std::sqrt(s.rmse / truth.size()), s.bias /= truth.size();
  return s;
}

struct Variant {
  const char* name;
  MarchOptions march;
};

std::vector<Variant> variants() {
  // NS09's march (B-spline levels, smooth max) and one change at a time from it, then
  // the shipped default (bilinear levels, plain max: docs/quality-presets.md).
  Variant ns09{"NS09 (W 32, k_v 4, o_v 3, B-spline levels, smooth max)", {}};
  ns09.march.method = HorizonMethod::March;
  set_level_sampling(ns09.march, LevelSampling::BSpline);
  ns09.march.smooth_max = true;
  std::vector<Variant> v = {ns09};
  auto from_ns09 = [&](const char* name, auto change) {
    Variant x{name, ns09.march};
    change(x.march);
    v.push_back(x);
  };
  from_ns09("plain max", [](MarchOptions& m) { m.smooth_max = false; });
  from_ns09("o_v 2", [](MarchOptions& m) { m.level_offset = 2; });
  from_ns09("o_v 1", [](MarchOptions& m) { m.level_offset = 1; });
  from_ns09("k_v 8", [](MarchOptions& m) { m.k_v = 8; });
  from_ns09("W 64", [](MarchOptions& m) { m.azimuths = 64; });
  from_ns09("bilinear levels", [](MarchOptions& m) { set_level_sampling(m, LevelSampling::Bilinear); });
  from_ns09("no pyramid (level 0 bilinear)", [](MarchOptions& m) { set_level_sampling(m, LevelSampling::None); });
  Variant march{"the default march: bilinear levels, plain max", {}};
  march.march.method = HorizonMethod::March;
  v.push_back(march);
  Variant flat_plain{"no pyramid, plain max", march.march};
  set_level_sampling(flat_plain.march, LevelSampling::None);
  v.push_back(flat_plain);
  // The sweep (horizon_sweep.h) at (near steps K, lines per texel); projected crops only.
  for (const auto& [k, lines, name] : {std::tuple{2, 1, "sweep, K 2, 1 line"}, std::tuple{4, 1, "**default**: sweep, K 4, 1 line"},
                                       std::tuple{4, 2, "sweep, K 4, 2 lines"}, std::tuple{8, 3, "sweep, K 8, 3 lines"}}) {
    Variant x{name, {}};
    x.march.method = HorizonMethod::Sweep;
    x.march.sweep_near_steps = k;
    x.march.sweep_lines = lines;
    v.push_back(x);
  }
  return v;
}

void row(const char* name, const Stats& svf, const Stats& sky, double secs) {
  std::printf("| %s | %.4f | %.4f | %+.4f | %.4f | %.4f | %+.4f | %.2f |\n", name, svf.rmse, svf.max_abs, svf.bias,
              sky.rmse, sky.max_abs, sky.bias, secs);
}

}  // namespace

int main(int argc, char** argv) {
  const int stride = argc > 1 ? std::max(1, std::atoi(argv[1])) : 2;
  const std::string dir = std::string(SKYLIT_SHARED_DIR) + "/dem/";
  std::printf("# Horizon-march accuracy: default vs exact\n\n");
  std::printf("Truth: exact march (every half texel, bilinear, to the DEM edge, Earth curvature k = 0.13), "
              "%d azimuths, at every %d-th texel in x and y. Errors are product value − truth. "
              "Threads: %u.\n\n",
              kTruthAzimuths, stride, std::max(1u, std::thread::hardware_concurrency()));
  for (const Crop& c : kCrops) {
    terrain::DemReadOptions ro;
    ro.window = c.window;
    const terrain::HeightField f = terrain::read_dem(dir + c.file, ro).field;
    const auto t0 = std::chrono::steady_clock::now();
    const Truth truth = ground_truth(f, stride, 32);
    const double truth_secs = seconds_since(t0);
    std::printf("## %s — %s\n\n", c.file, c.what);
    std::printf("Window %d×%d at (%d, %d), dx %.1f–%.1f m, dy %.1f m; %zu truth texels (%.1f s); "
                "mean truth svf %.4f, skyview %.4f.\n\n",
                f.width, f.height, c.window.x0, c.window.y0, f.dx_per_row.front(), f.dx_per_row.back(), f.dy,
                truth.ii.size(), truth_secs, [&] { double s = 0; for (double v : truth.svf) s += v; return s / truth.svf.size(); }(),
                [&] { double s = 0; for (double v : truth.skyview) s += v; return s / truth.skyview.size(); }());
    std::printf("| march | svf RMSE | svf max | svf bias | skyview RMSE | skyview max | skyview bias | time (s) |\n");
    std::printf("| --- | --- | --- | --- | --- | --- | --- | --- |\n");
    row("exact horizons, W 32 (azimuth sampling alone)",
        compare(truth.svf, [&](std::size_t k) { return truth.svf_w[k]; }),
        compare(truth.skyview, [&](std::size_t k) { return truth.skyview_w[k]; }), 0.0);
    for (const Variant& v : variants()) {
      ProductOptions o;
      o.march = v.march;
      if (o.march.method == HorizonMethod::Sweep && !uses_sweep(f, o)) continue;  // it would march
      const auto t1 = std::chrono::steady_clock::now();
      const ProductBands svf = compute_product(f, Product::Svf, o);
      const ProductBands sky = compute_product(f, Product::Skyview, o);
      const double secs = seconds_since(t1);
      row(v.name, compare(truth.svf, [&](std::size_t k) { return svf.at(0, truth.ii[k], truth.jj[k]); }),
          compare(truth.skyview, [&](std::size_t k) { return sky.at(0, truth.ii[k], truth.jj[k]); }), secs);
    }
    // The horizon product itself, per band, in degrees. Truth is floored at 0: the
    // curvature floor (≈ −1e-5°) is below the table's precision.
    auto horizon_row = [&](const char* what, const ProductOptions& o) {
      const ProductBands hz = compute_product(f, Product::Horizon, o);
      std::vector<double> truth_deg, got_deg;
      for (std::size_t k = 0; k < truth.ii.size(); ++k)
        for (int b = 0; b < 32; ++b) {
          truth_deg.push_back(truth.horizon_deg[k * 32 + b]);
          got_deg.push_back(std::max(0.0, static_cast<double>(hz.at(b, truth.ii[k], truth.jj[k]))));
        }
      const Stats h = compare(truth_deg, [&](std::size_t k) { return got_deg[k]; });
      std::printf("\n`horizon` product, %s, all 32 bands: RMSE %.2f°, max |error| %.2f°, bias %+.2f°.\n", what, h.rmse,
                  h.max_abs, h.bias);
    };
    ProductOptions marched;
    marched.march.method = HorizonMethod::March;
    horizon_row("default march", marched);
    if (uses_sweep(f, ProductOptions{})) horizon_row("default sweep (K 4, 1 line)", ProductOptions{});
    std::printf("\n");
    std::fflush(stdout);
  }
  return 0;
}
