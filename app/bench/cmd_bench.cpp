// `skylit bench [DEM]`: sweeps the quality settings, times a frame per setting and
// measures its error against the brute-force ground truth; prints a table, writes a
// CSV and an SVG of error against time with the Pareto front (the basis of the
// --quality presets, docs/quality-presets.md).
#include "app/bench/bench_front.h"
#include "app/bench/bench_output.h"
#include "app/bench/bench_run.h"
#include "app/bench/svg_plot.h"
#include "app/common/sign_checks.h"
#include "app/common/text_file.h"
#include "app/commands.h"
#include "gpu/renderer_factory.h"

#include "terrain/dem_reader.h"
#include "terrain/synthetic.h"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>

namespace skylit::app::bench {
namespace {

struct BenchArgs {
  std::vector<std::string> dems;
  std::vector<int> sizes = {512, 1024, 2048, 4096};
  std::uint64_t seed = 1;
  std::string backend = gpu::backend_names().front();
  std::string sweep = "default";
  std::string clock = clock_names().front();
  std::string csv, plot, front;
  bool with_synthetic = false;  // --front: the synthetic scene too, next to the DEMs
  BenchConfig config;
  bool sizes_given = false;
};

BenchScene synthetic_scene(int size, std::uint64_t seed) {
  terrain::SyntheticOptions opt;
  opt.width = opt.height = size;
  opt.seed = seed;
  return {"synthetic", terrain::make_synthetic_terrain(opt)};
}

int run_bench(const BenchArgs& a) {
  if (!a.dems.empty() && a.sizes_given && !a.with_synthetic)
    throw std::invalid_argument("--sizes applies to the built-in scenes; a DEM is benchmarked at its own size");
  const std::vector<BenchSetting> settings = sweep_settings(a.sweep);
  const auto timing = make_timing_source(a.backend, a.clock);  // "auto" resolved here, once
  const auto truth_timing = make_timing_source(a.config.truth_backend, std::string(kWallClock));
  // Fail on bad output paths before hours of work, leaving nothing behind.
  if (!a.csv.empty()) check_writable(a.csv, "CSV");
  if (!a.plot.empty()) check_writable(a.plot, "plot");
  if (!a.front.empty()) check_writable(a.front, "front");

  std::cerr << "skylit: bench: " << settings.size() << " settings (--sweep " << a.sweep << "), " << a.config.runs
            << " runs after " << a.config.warmup << " warm-up, backend " << timing->backend() << ", "
            << timing->clock() << " clock\n";
  std::vector<BenchRow> rows;
  std::optional<std::pair<int, double>> measured_truth;
  auto note = [](const std::string& line) { std::cerr << "skylit: " << line << "\n"; };
  print_table_header(std::cout);
  auto bench_one = [&](const BenchScene& scene) {
    auto scene_rows = run_scene(scene, settings, a.config, *timing, *truth_timing, measured_truth,
                                [](const BenchRow& r) { print_table_row(std::cout, r); }, note);
    rows.insert(rows.end(), scene_rows.begin(), scene_rows.end());
  };
  for (const std::string& dem : a.dems) {
    auto read = terrain::read_dem(dem);
    for (const auto& w : read.warnings) std::cerr << "skylit: warning: " << w << "\n";
    bench_one({std::filesystem::path(dem).filename().string(), std::move(read.field)});
  }
  if (a.dems.empty() || a.with_synthetic)
    for (int size : a.sizes) bench_one(synthetic_scene(size, a.seed));
  if (!a.csv.empty()) write_text_atomically(a.csv, csv_text(rows), "CSV");
  if (!a.plot.empty()) write_text_atomically(a.plot, pareto_svg(rows), "plot");
  if (!a.front.empty())
    write_text_atomically(a.front,
                          front_csv_text(rows, "skylit bench --sweep " + a.sweep + " --backend " + std::string(timing->backend()) +
                                                   ", " + std::string(timing->clock()) + " clock, " + std::to_string(a.config.runs) +
                                                   " runs"),
                          "front");
  return 0;
}

}  // namespace

void add_bench_command(CLI::App& root, Action& run) {
  auto args = std::make_shared<BenchArgs>();
  auto* cmd = root.add_subcommand(
      "bench", "Sweep quality settings: time per frame and error against brute force, CSV and Pareto plot");
  cmd->add_option("DEM", args->dems, "DEM rasters to benchmark, each at its own size (default: the built-in synthetic scene at --sizes)");
  cmd->add_option("--sizes", args->sizes, "Sides of the built-in scenes, comma-separated")
      ->delimiter(',')->check(CLI::Range(2, 16384))->capture_default_str()
      ->each([args](const std::string&) { args->sizes_given = true; });
  cmd->add_option("--seed", args->seed, "Seed of the built-in scenes")->capture_default_str();
  cmd->add_option("--backend", args->backend, "Compute backend: auto, gpu, reference")->capture_default_str();
  cmd->add_option("--runs", args->config.runs, "Timed runs per setting (the median is reported)")
      ->check(CLI::Range(1, 100000))->capture_default_str();
  cmd->add_option("--warmup", args->config.warmup, "Untimed runs before the timed ones")
      ->check(CLI::Range(0, 100000))->capture_default_str();
  cmd->add_option("--clock", args->clock,
                  "auto (gpu on the gpu backend, else wall) | wall | cpu (process CPU time, all threads: steadier "
                  "on a shared machine) | gpu (GL timer queries; wall where the driver has none)")
      ->capture_default_str();
  cmd->add_option("--sweep", args->sweep, "smoke | default | full (every combination, for GPU machines)")
      ->capture_default_str();
  cmd->add_option("--truth-max-size", args->config.truth_max_size,
                  "Largest scene side that gets the brute-force ground truth (larger: errors NA)")
      ->check(app::non_negative_number())->capture_default_str();
  cmd->add_option("--truth-backend", args->config.truth_backend,
                  "Backend of the ground truth (the CPU reference is the oracle; gpu is faster)")
      ->capture_default_str();
  cmd->add_option("--threads", args->config.threads, "Worker threads of the reference backend (0: all cores)")
      ->check(app::non_negative_number())->capture_default_str();
  cmd->add_option("-o,--output", args->csv, "CSV of all settings (written atomically)");
  cmd->add_option("--front", args->front,
                  "CSV of the speed/error front over all scenes, per product, for skylit shade --max-error "
                  "(data/quality/front.csv; scripts/make_quality_front.sh)");
  cmd->add_flag("--with-synthetic", args->with_synthetic, "Bench the synthetic scene at --sizes next to the DEMs");
  cmd->add_option("--plot", args->plot, "SVG of error against time with the Pareto front");
  cmd->callback([&run, args] { run = [args] { return run_bench(*args); }; });
}

}  // namespace skylit::app::bench
