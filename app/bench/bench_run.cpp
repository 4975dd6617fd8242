#include "app/bench/bench_run.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <thread>
#include <tuple>
#include <vector>

namespace skylit::app::bench {
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
  shading::ProductBands skyview, shaded, svf;
  // shaded at (n, N, wedge) of the settings that asked, computed at first need.
  std::vector<std::pair<std::tuple<int, int, sh::WedgeInterpolation>, shading::ProductBands>> same_order;
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
  FrameTime skyview_time, shaded_time;
  Truth truth{timing.compute(scene.field, Product::Skyview, options, skyview_time),
              timing.compute(scene.field, Product::Shaded, options, shaded_time), {}, {}};
  FrameTime svf_time;
  truth.svf = timing.compute(scene.field, Product::Svf, options, svf_time);
  const double seconds = (skyview_time.wall_ms + shaded_time.wall_ms + svf_time.wall_ms) / 1000.0;
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
                                const BenchConfig& config, TimingSource& timing, TimingSource& truth_timing,
                                std::optional<std::pair<int, double>>& measured_truth, const RowCallback& on_row,
                                const NoteCallback& note) {
  std::optional<Truth> truth = compute_truth(scene, config, truth_timing, measured_truth, note);
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  std::vector<BenchRow> rows;
  for (const BenchSetting& s : settings) {
    const shading::ProductOptions options = options_for(s, config.threads);
    BenchRow row{scene.name, scene.size(), std::string(timing.backend()), "NA", s, {kNaN, kNaN, kNaN}, kNaN,
                 {kNaN, kNaN}, {kNaN, kNaN}, std::nullopt};
    // Skipped, not timed on another backend: the rows of one run share a backend.
    if (const auto why = timing.lacks(Product::Shaded, options)) {
      row.skipped = *why;
      note(s.label() + " skipped on " + row.backend + ": " + *why);
      on_row(row);
      rows.push_back(row);
      continue;
    }
    std::vector<FrameTime> runs;
    shading::ProductBands shaded;
    for (int r = 0; r < config.warmup + config.runs; ++r) {
      FrameTime t;
      shaded = timing.compute(scene.field, Product::Shaded, options, t);
      if (r >= config.warmup) runs.push_back(t);
    }
    ClockedTimes times = timing.frame_times(runs);
    row.clock = times.clock;
    row.frame_ms = time_stats(std::move(times.ms));
    std::vector<double> walls;
    for (const FrameTime& t : runs) walls.push_back(t.wall_ms);
    row.wall_ms_median = time_stats(walls).median;
    if (truth) {
      row.shaded = error_stats(shaded, truth->shaded);
      const auto key = std::tuple{s.sh_order, s.nlp_order, s.wedge};
      auto same_order = std::find_if(truth->same_order.begin(), truth->same_order.end(),
                                     [&](const auto& entry) { return entry.first == key; });
      if (same_order == truth->same_order.end()) {
        shading::ProductOptions o = truth_options(config.threads);
        o.shaded.sh_order = s.sh_order;
        o.shaded.nlp_order = s.nlp_order;
        o.shaded.wedge = s.wedge;
        FrameTime t;
        truth->same_order.emplace_back(key, truth_timing.compute(scene.field, Product::Shaded, o, t));
        note("ground truth at n " + std::to_string(s.sh_order) + ", N " + std::to_string(s.nlp_order) + ", " +
             std::string(wedge_name(s.wedge)) + " wedge: " + format_duration(t.wall_ms / 1000.0));
        same_order = truth->same_order.end() - 1;
      }
      row.shaded_same_order = error_stats(shaded, same_order->second);
      // skyview depends on the march only: reuse the error of an earlier equal march.
      const auto same = std::find_if(rows.begin(), rows.end(), [&](const BenchRow& r) {
        return !r.skipped && r.setting.same_march(s);
      });
      if (same != rows.end()) {
        row.skyview = same->skyview;
        row.svf = same->svf;
        row.svf_ms = same->svf_ms;
        row.skyview_ms = same->skyview_ms;
      } else if (const auto why = timing.lacks(Product::Skyview, options)) {
        note(s.label() + ": skyview error NA on " + row.backend + ": " + *why);
      } else {
        FrameTime t;
        row.skyview = error_stats(timing.compute(scene.field, Product::Skyview, options, t), truth->skyview);
        row.skyview_ms = t.host_ms;
        if (!timing.lacks(Product::Svf, options)) {
          FrameTime v;
          row.svf = error_stats(timing.compute(scene.field, Product::Svf, options, v), truth->svf);
          row.svf_ms = v.host_ms;
        }
      }
    }
    on_row(row);
    rows.push_back(row);
  }
  return rows;
}

}  // namespace skylit::app::bench
