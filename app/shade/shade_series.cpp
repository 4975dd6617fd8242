#include "app/shade/shade_series.h"

#include "app/common/progress.h"
#include "gpu/timer.h"
#include "shading/time_integral.h"
#include "shading/time_series.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <future>
#include <iostream>
#include <string>

namespace skylit::app::shade {
namespace {

// One frame's lighting: the request at instant t.
shading::ResolvedLighting lighting_at(const SeriesJob& job, sky::UtcTime t) {
  shading::LightingRequest r = job.request;
  r.time = shading::format_instant(t);
  return shading::resolve_lighting(r, job.place);
}

void print_frame_times(const std::vector<double>& ms, int sun_far_kept) {
  if (ms.empty()) return;
  std::fprintf(stderr, "skylit: time %-28s %9d of %zu\n", "frames keeping the sun's far", sun_far_kept, ms.size());
  std::fprintf(stderr, "skylit: time %-28s %9.1f ms\n", "frame 1", ms.front());
  if (ms.size() < 2) return;
  double later = 0.0;
  for (std::size_t k = 1; k < ms.size(); ++k) later += ms[k];
  later /= static_cast<double>(ms.size() - 1);
  std::fprintf(stderr, "skylit: time %-28s %9.1f ms (%.0f %% of frame 1)\n", "frames 2.. (mean)", later,
               100.0 * later / ms.front());
  // The median: in a replay most frames keep the sun's horizon, a few sweep it again.
  std::vector<double> rest(ms.begin() + 1, ms.end());
  std::nth_element(rest.begin(), rest.begin() + static_cast<std::ptrdiff_t>(rest.size() / 2), rest.end());
  const double median = rest[rest.size() / 2];
  std::fprintf(stderr, "skylit: time %-28s %9.1f ms (%.0f %% of frame 1)\n", "frames 2.. (median)", median,
               100.0 * median / ms.front());
}

}  // namespace

void run_series(shading::Renderer& renderer, const terrain::HeightField& field, const SeriesJob& job) {
  const int n = static_cast<int>(job.instants.size());
  renderer.expect_frames(n);
  renderer.expect_blockers(static_cast<bool>(job.spheres_at));
  std::optional<shading::SeriesSum> sum;
  if (job.summed) sum.emplace(*job.summed, job.instants, field.width, field.height);
  const std::string label = job.summed ? std::string(shading::summed_product_name(*job.summed))
                                       : std::string(shading::product_name(job.product));
  std::vector<std::string> written;  // removed again if a later frame fails
  shading::ProductBands all;         // the multi-band file
  std::vector<double> frame_ms;
  int sun_far_kept = 0;  // frames that kept the sun's swept far slopes (Renderer::set_sun_heading_tolerance)
  int night = 0;
  // Frame k's file is written on another thread while frame k + 1 renders: the encoder
  // (PNG: ≈ 80 ms at 1024²) then overlaps the sun pass instead of following it.
  std::future<void> writing;
  const auto wait_for_write = [&] {
    if (writing.valid()) writing.get();  // rethrows the writer's error here
  };
  try {
    ProgressBar bar(label + " (" + std::to_string(n) + " frames)", job.quiet);
    for (int k = 0; k < n; ++k) {
      const shading::ResolvedLighting lit = lighting_at(job, job.instants[k]);
      if (!shading::sun_above_horizon(lit.lighting.sun)) ++night;
      if (sum && !sum->needs_frame(k, lit.lighting)) continue;
      const auto start = std::chrono::steady_clock::now();
      shading::ProductBands frame = renderer.frame(job.product,
                                                   {lit.lighting,
                                                    job.spheres_at ? job.spheres_at(job.instants[k].unix_seconds)
                                                                   : std::vector<blockers::Sphere>{},
                                                    std::nullopt}, [&](double f) {
        bar.update((k + f) / n);
      });
      frame_ms.push_back(gpu::ms_since(start));
      if (renderer.last_timings().sun_far_reused) ++sun_far_kept;
      if (sum) {
        sum->add(k, frame);
      } else if (job.outputs.per_frame) {
        wait_for_write();
        written.push_back(job.outputs.files[k].path);
        writing = std::async(std::launch::async, [&spec = job.outputs.files[k], &field, frame = std::move(frame)] {
          write_product(spec, field, frame);
        });
      } else {
        if (all.data.empty()) all = {frame.width, frame.height, 0, {}, {}};
        all.data.insert(all.data.end(), frame.data.begin(), frame.data.end());
        const auto names = frame_band_names(frame, job.instants[k]);
        all.band_names.insert(all.band_names.end(), names.begin(), names.end());
        all.bands += frame.bands;
      }
    }
    wait_for_write();
    bar.finish();
    if (sum) {
      write_product(job.outputs.files.front(), field, sum->result(field.valid));
    } else if (!job.outputs.per_frame) {
      write_product(job.outputs.files.front(), field, all);
    }
  } catch (...) {
    try {
      wait_for_write();  // before its file is removed
    } catch (...) {  // the first error is the one reported
    }
    std::error_code ec;
    for (const std::string& path : written) std::filesystem::remove(path, ec);
    throw;
  }
  if (job.timings) print_frame_times(frame_ms, sun_far_kept);
  if (job.quiet) return;
  if (!frame_ms.empty())
    std::cerr << "skylit: computed " << frame_ms.size() << " frame" << (frame_ms.size() == 1 ? "" : "s") << " on "
              << renderer.description() << "\n";
  if (night > 0)
    std::cerr << "skylit: note: the sun is below the horizon at " << night << " of " << n << " times ("
              << (shading::traits(job.product).sun_only ? "shadow 0 there" : "sky light only there") << ")\n";
  if (job.outputs.per_frame)
    std::cerr << "skylit: wrote " << n << " files, " << job.outputs.files.front().path << " … "
              << job.outputs.files.back().path << "\n";
  else
    std::cerr << "skylit: wrote " << job.outputs.files.front().path << " ("
              << (sum ? std::string(shading::summed_product_unit(*job.summed)) : std::to_string(all.bands) + " bands")
              << ")\n";
}

}  // namespace skylit::app::shade
