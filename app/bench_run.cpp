#include "app/bench_run.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <thread>

namespace skylit::app {
namespace {

using shading::Product;

// docs/performance.md: the exact march costs ≈ 5.9 µs per texel·azimuth at 512² on
// one core of the 2-core CI machine, growing linearly with the side (one sample per
// half texel along the ray).
constexpr double kExactSecondsPerTexelAzimuthAt512 = 5.9e-6;
constexpr int kExactCalibrationSide = 512;

std::string format_duration(double seconds) {
  char buf[64];
  if (seconds < 120) std::snprintf(buf, sizeof buf, "%.0f s", seconds);
  else if (seconds < 7200) std::snprintf(buf, sizeof buf, "%.0f min", seconds / 60);
  else std::snprintf(buf, sizeof buf, "%.1f h", seconds / 3600);
  return buf;
}

struct Truth {
  shading::ProductBands skyview, shaded;
};

// The truth of both products, or nothing when the scene is above --truth-max-size.
std::optional<Truth> compute_truth(const BenchScene& scene, const BenchConfig& config, TimingSource& timing,
                                   std::optional<std::pair<int, double>>& measured, const NoteCallback& note) {
  const int side = std::max(scene.field.width, scene.field.height);
  const bool estimable = measured || config.truth_backend == kOracleBackend;
  const std::string estimate =
      estimable ? " (≈ " + format_duration(estimate_truth_seconds(scene.field.width, scene.field.height,
                                                                  config.threads, measured)) + ")"
                : "";
  if (side > config.truth_max_size) {
    note("ground truth for " + scene.name + " " + scene.size() + " skipped" + estimate + ": side > --truth-max-size " +
         std::to_string(config.truth_max_size) + "; errors are NA");
    return std::nullopt;
  }
  note("ground truth for " + scene.name + " " + scene.size() + ": brute force on " + config.truth_backend + estimate +
       " …");
  const shading::ProductOptions options = truth_options(config.threads);
  double ms_skyview = 0, ms_shaded = 0;
  Truth truth{timing.compute(scene.field, Product::Skyview, options, ms_skyview),
              timing.compute(scene.field, Product::Shaded, options, ms_shaded)};
  const double seconds = (ms_skyview + ms_shaded) / 1000.0;
  note("ground truth for " + scene.name + " " + scene.size() + ": " + format_duration(seconds));
  if (!measured || side > measured->first) measured = std::pair{side, seconds};
  return truth;
}

}  // namespace

std::string BenchScene::size() const {
  if (field.width == field.height) return std::to_string(field.width);
  return std::to_string(field.width) + "x" + std::to_string(field.height);
}

double estimate_truth_seconds(int width, int height, unsigned threads,
                              const std::optional<std::pair<int, double>>& measured) {
  const double side = std::max(width, height), area = static_cast<double>(width) * height;
  if (measured) {  // texels × the length of each ray
    const double m = measured->first;
    return measured->second * area / (m * m) * side / m;
  }
  const unsigned workers = threads ? threads : std::max(1u, std::thread::hardware_concurrency());
  const double per_call = kExactSecondsPerTexelAzimuthAt512 * side / kExactCalibrationSide;
  const int products = 2;  // skyview and shaded each march
  return products * per_call * width * height * shading::ExactOptions{}.sky_azimuths / workers;
}

std::vector<BenchRow> run_scene(const BenchScene& scene, const std::vector<BenchSetting>& settings,
                                const BenchConfig& config, TimingSource& timing, const std::string& backend,
                                TimingSource& truth_timing, std::optional<std::pair<int, double>>& measured_truth,
                                const RowCallback& on_row, const NoteCallback& note) {
  const std::optional<Truth> truth = compute_truth(scene, config, truth_timing, measured_truth, note);
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  std::vector<BenchRow> rows;
  for (const BenchSetting& s : settings) {
    const shading::ProductOptions options = options_for(s, config.threads);
    BenchRow row{scene.name, scene.size(), backend, std::string(timing.clock()), s, {}, {kNaN, kNaN}, {kNaN, kNaN}};
    std::vector<double> samples;
    shading::ProductBands shaded;
    for (int r = 0; r < config.warmup + config.runs; ++r) {
      double ms = 0;
      shaded = timing.compute(scene.field, Product::Shaded, options, ms);
      if (r >= config.warmup) samples.push_back(ms);
    }
    row.frame_ms = time_stats(samples);
    if (truth) {
      row.shaded = error_stats(shaded, truth->shaded);
      // skyview depends on the march only: reuse the error of an earlier equal march.
      const auto same = std::find_if(rows.begin(), rows.end(), [&](const BenchRow& r) { return r.setting.same_march(s); });
      if (same != rows.end()) {
        row.skyview = same->skyview;
      } else {
        double ms = 0;
        row.skyview = error_stats(timing.compute(scene.field, Product::Skyview, options, ms), truth->skyview);
      }
    }
    on_row(row);
    rows.push_back(row);
  }
  return rows;
}

}  // namespace skylit::app
