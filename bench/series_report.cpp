// Time series on one renderer (shading/renderer.h), for docs/performance.md: the time of
// a series' first frame against the later ones (shadow and lit shaded), and a day's
// insolation and sun hours at the default step against the 1-minute step on the same
// horizons (the truth of the step, docs/time-step.md's question asked on a real field).
// Usage: series_report DEM [DATE] [BACKEND]; e.g. series_report scene.tif 2026-06-21 auto
// (the DEM from `skylit scene --size 1024`). Prints markdown tables.
#include "gpu/renderer_factory.h"
#include "shading/lighting.h"
#include "shading/summed_products.h"
#include "shading/time_integral.h"
#include "shading/time_series.h"
#include "terrain/dem_reader.h"
#include "terrain/geolocation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace skylit;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

shading::Lighting lighting_at(sky::UtcTime t, const sky::Observer& place, const std::string& sky) {
  shading::LightingRequest r;
  r.time = shading::format_instant(t);
  r.sky = sky;
  return shading::resolve_lighting(r, place).lighting;
}

// Frame times of `instants` on a fresh renderer: [0] the first frame, then the others.
std::vector<double> series_times(gpu::Backend backend, const terrain::HeightField& field, shading::Product product,
                                 const std::vector<sky::UtcTime>& instants, const sky::Observer& place,
                                 const std::string& sky, double& setup_ms, std::string& on) {
  const auto start = Clock::now();
  auto renderer = gpu::make_renderer(backend);
  setup_ms = ms_since(start);
  renderer->set_field(field);
  renderer->set_options({});
  renderer->expect_frames(static_cast<int>(instants.size()));
  std::vector<double> ms;
  for (sky::UtcTime t : instants) {
    const shading::Lighting l = lighting_at(t, place, sky);
    const auto f0 = Clock::now();
    renderer->frame(product, {l, {}, std::nullopt});
    ms.push_back(ms_since(f0));
  }
  on = renderer->description();
  return ms;
}

struct Sum {
  std::vector<float> values;
  double ms = 0.0;
  std::size_t frames = 0;
};

Sum day_sum(shading::Renderer& renderer, const terrain::HeightField& field, shading::SummedProduct product,
            const shading::TimeSeries& ts, const sky::Observer& place) {
  const auto start = Clock::now();
  renderer.expect_frames(static_cast<int>(ts.instants.size()));
  shading::SeriesSum sum(product, ts.instants, field.width, field.height);
  Sum out;
  for (std::size_t k = 0; k < ts.instants.size(); ++k) {
    const shading::Lighting l = lighting_at(ts.instants[k], place, "uniform");
    if (!sum.needs_frame(static_cast<int>(k), l)) continue;
    sum.add(static_cast<int>(k), renderer.frame(shading::frame_product(product), {l, {}, std::nullopt}));
    ++out.frames;
  }
  out.values = sum.result(field.valid).data;
  out.ms = ms_since(start);
  return out;
}

void print_error(const char* name, const char* unit, const Sum& coarse, const Sum& fine) {
  double sum_abs = 0.0, max_abs = 0.0, sum_fine = 0.0, max_rel = 0.0;
  std::size_t n = 0;
  for (float v : fine.values)
    if (!std::isnan(v)) sum_fine += v, ++n;
  const double floor = 0.01 * sum_fine / n;  // relative errors where the truth is ≥ 1 % of its mean
  for (std::size_t t = 0; t < fine.values.size(); ++t) {
    if (std::isnan(fine.values[t])) continue;
    const double d = std::abs(static_cast<double>(coarse.values[t]) - fine.values[t]);
    sum_abs += d;
    max_abs = std::max(max_abs, d);
    if (fine.values[t] >= floor) max_rel = std::max(max_rel, d / fine.values[t]);
  }
  std::vector<double> errors;
  for (std::size_t t = 0; t < fine.values.size(); ++t)
    if (!std::isnan(fine.values[t])) errors.push_back(std::abs(static_cast<double>(coarse.values[t]) - fine.values[t]));
  std::sort(errors.begin(), errors.end());
  const double p99 = errors.empty() ? 0.0 : errors[errors.size() * 99 / 100];
  std::printf("| %s | %.1f s (%zu frames) | %.1f s (%zu frames) | %.4g %s (%.3f %%) | %.4g %s | %.4g %s | %.2f %% |\n",
              name, coarse.ms / 1e3, coarse.frames, fine.ms / 1e3, fine.frames, sum_abs / n, unit,
              100.0 * sum_abs / sum_fine, p99, unit, max_abs, unit, 100.0 * max_rel);
}

}  // namespace

int main(int argc, char** argv) try {
  if (argc < 2) {
    std::fprintf(stderr, "usage: series_report DEM [DATE] [auto|gpu|reference]\n");
    return 2;
  }
  const std::string date = argc > 2 ? argv[2] : "2026-06-21";
  const auto backend = gpu::parse_backend(argc > 3 ? argv[3] : "auto");
  if (!backend) throw std::invalid_argument("unknown backend");
  const auto read_start = Clock::now();
  const terrain::HeightField field = terrain::read_dem(argv[1]).field;
  const double read_ms = ms_since(read_start);
  const auto centre = terrain::grid_centre_lat_lon(field.georef, field.width, field.height);
  if (!centre) throw std::invalid_argument("the DEM has no CRS");
  const sky::Observer place{centre->latitude_deg, centre->longitude_deg, 0.0};

  // 24 frames, 30 min apart, from 06:00 local mean solar time.
  const double noon_utc = 12.0 - place.longitude_deg / 15.0;
  const sky::UtcTime day0 = sky::parse_utc_time(date + "T00:00Z");
  std::vector<sky::UtcTime> frames;
  for (int k = 0; k < 24; ++k) frames.push_back({day0.unix_seconds + (noon_utc - 6.0 + 0.5 * k) * 3600.0});
  std::printf("%d x %d, read %.0f ms; 24 frames from %s every 30 min\n\n", field.width, field.height, read_ms,
              sky::format_utc_time(frames.front()).c_str());
  std::printf("| series | renderer set-up | frame 1 | frames 2-24 (mean) | ratio | 24 frames |\n|---|---|---|---|---|---|\n");
  for (const auto& [product, sky] : {std::pair{shading::Product::Shadow, std::string("uniform")},
                                     std::pair{shading::Product::Shaded, std::string("uniform")},
                                     std::pair{shading::Product::Shaded, std::string("preetham")}}) {
    double setup = 0.0;
    std::string on;
    const std::vector<double> ms = series_times(*backend, field, product, frames, place, sky, setup, on);
    double later = 0.0, all = 0.0;
    for (std::size_t k = 0; k < ms.size(); ++k) {
      all += ms[k];
      if (k) later += ms[k];
    }
    later /= static_cast<double>(ms.size() - 1);
    std::printf("| %s, %s sky | %.0f ms | %.0f ms | %.0f ms | %.1f %% | %.2f s (%s) |\n",
                std::string(shading::product_name(product)).c_str(), sky.c_str(), setup, ms[0], later,
                100.0 * later / ms[0], all / 1e3, on.c_str());
  }

  auto renderer = gpu::make_renderer(*backend);
  renderer->set_field(field);
  renderer->set_options({});
  const auto spec = [&](double step_s) {
    shading::TimeSeriesOptions o;
    o.day_step_seconds = step_s;
    return shading::resolve_time_series(shading::parse_time_spec(date, o), place);
  };
  const shading::TimeSeries coarse_ts = spec(shading::kDefaultDayStepSeconds), fine_ts = spec(60.0);
  std::printf("\n%s at lat %.3f lon %.3f: default step %.0f min against 1 min, same renderer and horizons\n\n",
              date.c_str(), place.latitude_deg, place.longitude_deg, shading::kDefaultDayStepSeconds / 60.0);
  std::printf("| product | default step | 1-min step | mean abs error | 99th percentile | max abs error | max rel error |\n"
              "|---|---|---|---|---|---|---|\n");
  for (const auto product : {shading::SummedProduct::Insolation, shading::SummedProduct::SunHours}) {
    const Sum coarse = day_sum(*renderer, field, product, coarse_ts, place);
    const Sum fine = day_sum(*renderer, field, product, fine_ts, place);
    print_error(std::string(shading::summed_product_name(product)).c_str(),
                std::string(shading::summed_product_unit(product)).c_str(), coarse, fine);
  }
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "series_report: %s\n", e.what());
  return 1;
}
