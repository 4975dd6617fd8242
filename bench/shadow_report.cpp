// Prints, as markdown, the accuracy of the sun's shadow fraction (sun_light.h) against
// the ground truth (dense half-texel march at 17 azimuths across the disc, disc
// integrated exactly) on crops of real DEMs at low sun, where shadows are long:
// mean |error|, RMSE, the share of texels whose error exceeds 0.5 (a lit/shadowed
// flip), the bias and the penumbra error, for the horizon marched in the sun's azimuth
// (a) and interpolated from W product azimuths (b), each with the sky's pyramid march
// and with the sun's level-0 march, and swept in the sun's azimuth (c; projected DEMs,
// the geographic one marches) (docs/accuracy.md (sun shadows)).
//
// Usage: shadow_report [crop_px]   (default 256; DEMs from SKYLIT_SHARED_DIR/dem)
#include "shading/sun_light.h"
#include "terrain/dem_reader.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

using namespace skylit;
using horizon::MarchOptions;
using shading::SunHorizon;
using shading::SunShadowOptions;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

struct Dem {
  const char* file;
  const char* label;
  int x0, y0;  // crop origin (px): a rugged part of the raster
};

struct Method {
  std::string name;
  SunShadowOptions options;
  bool core = false;
};

struct Stats {
  double mae = 0, rmse = 0, flips = 0, bias = 0;
  double penumbra_mae = 0;  // over texels whose true fraction is strictly between 0 and 1
};

Stats compare(const std::vector<float>& v, const std::vector<float>& truth) {
  Stats s;
  long n = 0, np = 0;
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (std::isnan(truth[k])) continue;
    if (truth[k] > 1e-4f && truth[k] < 1 - 1e-4f) {
      s.penumbra_mae += std::abs(static_cast<double>(v[k]) - truth[k]);
      ++np;
    }
    const double signed_error = static_cast<double>(v[k]) - truth[k], e = std::abs(signed_error);
    s.bias += signed_error;
    s.mae += e;
    s.rmse += e * e;
    s.flips += e > 0.5;
    ++n;
  }
  s.mae /= n;
  s.penumbra_mae /= std::max(np, 1L);
  s.bias /= n;
  s.rmse = std::sqrt(s.rmse / n);
  s.flips /= n;
  return s;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

MarchOptions level0(int k_v) {
  MarchOptions o;
  o.use_pyramid = false;
  o.smooth_max = false;
  o.k_v = k_v;
  return o;
}

SunShadowOptions marched(const MarchOptions& march, bool slope) {
  SunShadowOptions o;
  o.horizon = SunHorizon::Marched;
  o.march = march;
  o.disc_slope = slope;
  return o;
}

SunShadowOptions interpolated(MarchOptions march, int w) {
  SunShadowOptions o;
  o.horizon = SunHorizon::Interpolated;
  march.azimuths = w;
  o.march = march;
  return o;
}

// core: shown per DEM and sun position; the others only in the summary.
std::vector<Method> methods() {
  const MarchOptions sky;  // the sky's default march: pyramid, k_v = 4, o_v = 2, smoothed max
  std::vector<Method> m;
  m.push_back({"(a) default: level 0, k_v=32, A_s only", SunShadowOptions{}, true});
  m.push_back({"(a) level 0, k_v=32, A_s, A_s±δ", marched(level0(32), true), true});
  m.push_back({"(a) level 0, k_v=16, A_s only", marched(level0(16), false), false});
  m.push_back({"(a) level 0, k_v=16, A_s, A_s±δ", marched(level0(16), true), false});
  m.push_back({"(a) level 0, k_v=8, A_s only", marched(level0(8), false), false});
  m.push_back({"(a) sky march, A_s only", marched(sky, false), true});
  m.push_back({"(a) sky march, A_s, A_s±δ", marched(sky, true), false});
  MarchOptions finer = sky;
  finer.level_offset = 4.0;
  finer.k_v = 8;
  m.push_back({"(a) pyramid o_v=4, k_v=8, A_s, A_s±δ", marched(finer, true), false});
  for (int w : {16, 32, 64}) m.push_back({"(b) W=" + std::to_string(w) + ", sky march", interpolated(sky, w), true});
  for (int w : {16, 32, 64})
    m.push_back({"(b) W=" + std::to_string(w) + ", level 0, k_v=32", interpolated(shading::sun_march_options(), w), true});
  // (c) the horizon sweep in the sun's azimuth (projected DEMs; geographic ones march).
  for (const auto& [k, lines, core] : {std::tuple{4, 1, true}, std::tuple{4, 2, true}, std::tuple{8, 3, false},
                                               // near steps for lines: what each costs is in docs/accuracy.md
                                               std::tuple{8, 2, false}, std::tuple{16, 2, false}, std::tuple{16, 1, false},
                                               std::tuple{32, 1, false}, std::tuple{16, 3, false}}) {
    SunShadowOptions o;
    o.horizon = SunHorizon::Swept;
    o.march.method = horizon::HorizonMethod::Sweep;
    o.march.sweep_near_steps = k;
    o.march.sweep_lines = lines;
    m.push_back({"(c) sweep K " + std::to_string(k) + ", " + std::to_string(lines) + " line(s), A_s only", o, core});
  }
  SunShadowOptions dense3;
  dense3.horizon = SunHorizon::Exact;
  dense3.exact_columns = 3;
  m.push_back({"(a) exact march, A_s, A_s±δ", dense3, false});
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  const int crop = argc > 1 ? std::atoi(argv[1]) : 256;
  const std::string dir = std::string(SKYLIT_SHARED_DIR) + "/dem/";
  const std::vector<Dem> dems = {
      {"big_tujunga_srtm30_utm11n.tif", "Big Tujunga 30 m", 450, 150},
      {"similkameen_bc_50m_bcalbers.tif", "Similkameen 50 m", 80, 120},
      {"pyrenees_andorra_srtm3_4326.tif", "Pyrenees 3″ (≈68×93 m)", 300, 450},
  };
  const double elevations[] = {5 * kDeg, 10 * kDeg};
  const double azimuths[] = {137 * kDeg, 251 * kDeg};

  std::printf("| DEM (crop %d px) | sun az/el | shadowed / penumbra | method | mean abs | RMSE | err > 0.5 | bias | penumbra mean abs | time (s) |\n",
              crop);
  std::printf("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
  std::vector<std::vector<Stats>> totals(methods().size());
  std::vector<double> times(methods().size(), 0.0);
  double truth_seconds = 0.0;
  int cases = 0;
  for (const Dem& d : dems) {
    terrain::DemReadOptions ro;
    ro.window = terrain::PixelRect{d.x0, d.y0, crop, crop};
    const auto field = terrain::read_dem(dir + d.file, ro).field;
    for (double el : elevations)
      for (double az : azimuths) {
        const shading::SunAngles sun{az, el};
        SunShadowOptions truth_opt;
        truth_opt.horizon = SunHorizon::Exact;
        auto t0 = std::chrono::steady_clock::now();
        const auto truth = shading::shadow_fraction_field(field, sun, truth_opt);
        truth_seconds += seconds_since(t0);
        ++cases;
        std::fprintf(stderr, "%s az %.0f el %.0f: truth %.1f s\n", d.label, az / kDeg, el / kDeg, seconds_since(t0));
        long shadowed = 0, penumbra = 0, n = 0;
        for (float t : truth) {
          if (std::isnan(t)) continue;
          ++n;
          shadowed += t < 0.5f;
          penumbra += t > 1e-4f && t < 1 - 1e-4f;
        }
        int k = 0;
        for (const Method& m : methods()) {
          t0 = std::chrono::steady_clock::now();
          const auto v = shading::shadow_fraction_field(field, sun, m.options);
          const double secs = seconds_since(t0);
          const Stats s = compare(v, truth);
          times[k] += secs;
          totals[k++].push_back(s);
          if (!m.core) continue;
          std::printf("| %s | %.0f° / %.0f° | %.1f%% / %.1f%% | %s | %.4f | %.4f | %.2f%% | %+.4f | %.4f | %.2f |\n",
                      d.label, az / kDeg, el / kDeg, 100.0 * shadowed / n, 100.0 * penumbra / n, m.name.c_str(), s.mae,
                      s.rmse, 100.0 * s.flips, s.bias, s.penumbra_mae, secs);
          std::fflush(stdout);
        }
      }
  }
  std::printf("\n| method | mean abs | RMSE | err > 0.5 | bias | penumbra mean abs | time (s) |\n"
              "| --- | --- | --- | --- | --- | --- | --- |\n");
  int k = 0;
  for (const Method& m : methods()) {
    Stats mean;
    for (const Stats& s : totals[k])
      mean.mae += s.mae, mean.rmse += s.rmse, mean.flips += s.flips, mean.bias += s.bias,
      mean.penumbra_mae += s.penumbra_mae;
    const double n = static_cast<double>(totals[k].size());
    std::printf("| %s | %.4f | %.4f | %.2f%% | %+.4f | %.4f | %.2f |\n", m.name.c_str(), mean.mae / n, mean.rmse / n,
                100.0 * mean.flips / n, mean.bias / n, mean.penumbra_mae / n, times[k] / n);
    ++k;
  }
  std::printf("| ground truth (exact march, 17 columns) | 0 | 0 | 0 | 0 | 0 | %.2f |\n", truth_seconds / cases);
  return 0;
}
