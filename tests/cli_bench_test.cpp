// `skylit bench` end to end on a tiny scene: CSV layout, finite errors that fall from
// the lowest to the highest quality setting, a valid SVG with the Pareto front, and
// one-line errors that leave no files for bad arguments; on the gpu backend, the clock
// column and skipped settings; run_scene's median and skipping with a scripted source;
// the sweeps' sizes and their horizon-sweep settings.
#include "cli_test_util.h"
#include "gpu_test_util.h"

#include "app/bench/bench_output.h"
#include "app/bench/bench_run.h"
#include "app/bench/svg_plot.h"
#include "gpu/gl_context.h"
#include "shading/quality.h"
#include "shading/renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using skylit::testing::count_lines;
using skylit::testing::run_skylit;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> out;
  std::stringstream s(line);
  for (std::string cell; std::getline(s, cell, sep);) out.push_back(cell);
  if (!line.empty() && line.back() == sep) out.emplace_back();
  return out;
}

class CliBench : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() /
          ("skylit_bench_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  bool dir_empty() const { return fs::is_empty(dir); }
  fs::path dir;
};

const std::string kSmoke = "bench --sizes 32 --runs 2 --warmup 0 --sweep smoke --backend reference";

TEST_F(CliBench, SmokeSweepWritesCsvAndParetoPlot) {
  const fs::path csv = dir / "r.csv", svg = dir / "p.svg";
  const auto r = run_skylit(kSmoke + " -o " + csv.string() + " --plot " + svg.string());
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(count_lines(r.out), 1 + 3) << r.out;  // table header + the 3 smoke settings

  std::stringstream lines(slurp(csv));
  std::string header;
  std::getline(lines, header);
  EXPECT_EQ(header,
            "scene,size,backend,azimuths,k_v,level_offset,sh_order,nlp_order,subsample,wedge,levels,max,horizons,"
            "near_steps,sweep_lines,preset,clock,ms_median,ms_p10,ms_p90,wall_ms_median,skyview_rmse,skyview_max,shaded_rmse,shaded_max,"
            "shaded_same_order_rmse,shaded_same_order_max,status");
  const auto columns = split(header, ',');
  auto col = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(columns.begin(), columns.end(), name) - columns.begin());
  };
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(lines, line);) rows.push_back(split(line, ','));
  ASSERT_EQ(rows.size(), 3u);
  for (const auto& row : rows) {
    ASSERT_EQ(row.size(), columns.size());
    EXPECT_EQ(row[col("size")], "32");
    EXPECT_EQ(row[col("clock")], "wall");
    EXPECT_EQ(row[col("status")], "ok");
    EXPECT_EQ(row[col("ms_median")], row[col("wall_ms_median")]);  // the wall clock is the frame clock
    EXPECT_GT(std::stod(row[col("ms_median")]), 0.0);
    EXPECT_LE(std::stod(row[col("ms_p10")]), std::stod(row[col("ms_median")]));
    EXPECT_LE(std::stod(row[col("ms_median")]), std::stod(row[col("ms_p90")]));
    for (const char* e : {"skyview_rmse", "skyview_max", "shaded_rmse", "shaded_max", "shaded_same_order_rmse",
                          "shaded_same_order_max"}) {
      const double v = std::stod(row[col(e)]);
      EXPECT_TRUE(std::isfinite(v) && v >= 0.0) << e << " = " << row[col(e)];
    }
  }
  // The smoke sweep runs lowest → default → highest: a real check of the front.
  EXPECT_EQ(rows[0][col("azimuths")], "8");
  EXPECT_EQ(rows[0][col("subsample")], "4");
  EXPECT_EQ(rows[0][col("wedge")], "linear");
  EXPECT_EQ(rows[2][col("azimuths")], "64");
  EXPECT_EQ(rows[2][col("subsample")], "1");
  EXPECT_EQ(rows[2][col("wedge")], "bspline");
  EXPECT_EQ(rows[1][col("preset")], "default");
  for (const char* e : {"skyview_rmse", "shaded_rmse", "shaded_same_order_rmse"}) {
    EXPECT_GT(std::stod(rows[0][col(e)]), std::stod(rows[1][col(e)])) << e;
    EXPECT_GT(std::stod(rows[1][col(e)]), std::stod(rows[2][col(e)])) << e;
  }

  const std::string plot = slurp(svg);
  EXPECT_EQ(plot.rfind("<svg", 0), 0u);
  EXPECT_NE(plot.find("<polyline class=\"front\""), std::string::npos);
  EXPECT_NE(plot.find("</svg>"), std::string::npos);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 2);  // no temp files left
}

TEST_F(CliBench, BadArgumentsGiveOneLineErrorsAndNoFiles) {
  const std::string out = " -o " + (dir / "r.csv").string() + " --plot " + (dir / "p.svg").string();
  const std::vector<std::string> bad = {
      kSmoke + " -o " + (dir / "missing" / "r.csv").string(),  // unwritable CSV
      kSmoke + " --plot " + (dir / "missing" / "p.svg").string() + " -o " + (dir / "r.csv").string(),
      "bench --sizes 32 --runs 0 --sweep smoke" + out,
      "bench --sizes 32 --runs 2 --sweep smoke --backend nosuch" + out,
      "bench --sizes 32 --runs 2 --sweep nosuch" + out,
  };
  for (const auto& args : bad) {
    const auto r = run_skylit(args, /*merge_stderr=*/true);
    EXPECT_NE(r.status, 0) << args;
    EXPECT_EQ(count_lines(r.out), 1) << args << "\n" << r.out;
    EXPECT_NE(r.out.find("skylit: error:"), std::string::npos) << r.out;
    EXPECT_TRUE(dir_empty()) << args;
  }
}

TEST_F(CliBench, GpuSmokeSweepNamesItsClockAndSkipsWhatTheGpuLacks) {
  std::unique_ptr<skylit::gpu::HeadlessContext> probe;
  SKYLIT_CONTEXT_OR_SKIP(probe);
  probe.reset();  // the run below makes its own
  const fs::path csv = dir / "g.csv";
  const auto r = run_skylit("bench --sizes 16 --runs 2 --warmup 0 --sweep smoke --backend gpu -o " + csv.string(),
                            /*merge_stderr=*/true);
  ASSERT_EQ(r.status, 0) << r.out;
  std::stringstream lines(slurp(csv));
  std::string header;
  std::getline(lines, header);
  const auto columns = split(header, ',');
  auto col = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(columns.begin(), columns.end(), name) - columns.begin());
  };
  int rows = 0, timed = 0;
  for (std::string line; std::getline(lines, line); ++rows) {
    const auto row = split(line, ',');
    ASSERT_EQ(row.size(), columns.size()) << line;
    EXPECT_EQ(row[col("backend")], "gpu");
    const std::string clock = row[col("clock")];
    if (row[col("status")] == "skipped") {  // a knob the GPU pipeline lacks: named on stderr, not timed
      EXPECT_EQ(clock, "NA");
      EXPECT_EQ(row[col("ms_median")], "NA");
      EXPECT_NE(r.out.find(" skipped on gpu: "), std::string::npos) << r.out;
      continue;
    }
    ++timed;
    EXPECT_EQ(row[col("status")], "ok");
    // GPU timer queries, or the wall clock where the driver's timer reads ≈ 0 (llvmpipe).
    EXPECT_TRUE(clock == "gpu" || clock.rfind("wall (", 0) == 0) << clock;
    if (clock != "gpu") {
      EXPECT_NE(clock.find(": no GPU timer)"), std::string::npos) << clock;
    }
    EXPECT_GT(std::stod(row[col("ms_median")]), 0.0);
    EXPECT_GT(std::stod(row[col("wall_ms_median")]), 0.0);
    EXPECT_TRUE(std::isfinite(std::stod(row[col("shaded_rmse")])));
  }
  EXPECT_EQ(rows, 3);
  EXPECT_GE(timed, 1);  // the default preset has every knob at a value the GPU has
}

// A backend whose n-th computation takes n ms and which lacks B-spline wedges.
class ScriptedSource final : public skylit::app::bench::TimingSource {
 public:
  std::string_view backend() const override { return "scripted"; }
  std::string clock() const override { return "script"; }
  std::optional<std::string> lacks(skylit::shading::Product, const skylit::shading::ProductOptions& o) const override {
    if (o.shaded.wedge == skylit::sh::WedgeInterpolation::BSpline) return "no B-spline wedges";
    return std::nullopt;
  }
  skylit::shading::ProductBands compute(const skylit::terrain::HeightField& field, skylit::shading::Product,
                                        const skylit::shading::ProductOptions&, skylit::app::bench::FrameTime& t) override {
    t.host_ms = t.wall_ms = static_cast<double>(++calls);
    return {field.width, field.height, 1, std::vector<float>(field.size(), 0.5f), {"x"}};
  }
  skylit::app::bench::ClockedTimes frame_times(const std::vector<skylit::app::bench::FrameTime>& runs) const override {
    skylit::app::bench::ClockedTimes t{"script", {}};
    for (const auto& r : runs) t.ms.push_back(r.host_ms);
    return t;
  }
  int calls = 0;
};

TEST(BenchRunScene, MedianOverTheTimedRunsAndSkipsWhatTheBackendLacks) {
  using namespace skylit::app::bench;
  skylit::terrain::HeightField field(4, 4, 1.0);
  const BenchScene scene{"tiny", field};
  BenchConfig config;
  config.runs = 5;
  config.warmup = 2;
  config.truth_max_size = 0;  // no truth: timing only
  BenchSetting linear = sweep_settings("smoke")[1], bspline = linear;
  bspline.wedge = skylit::sh::WedgeInterpolation::BSpline;
  ScriptedSource timing, truth;
  std::optional<std::pair<int, double>> measured;
  std::vector<std::string> notes;
  const auto rows = run_scene(scene, {linear, bspline}, config, timing, truth, measured, [](const BenchRow&) {},
                              [&](const std::string& n) { notes.push_back(n); });
  ASSERT_EQ(rows.size(), 2u);
  // Calls 1–2 are the warm-up; the timed runs take 3…7 ms: median 5, p10 3.4, p90 6.6.
  EXPECT_EQ(timing.calls, config.warmup + config.runs);
  EXPECT_EQ(rows[0].clock, "script");
  EXPECT_DOUBLE_EQ(rows[0].frame_ms.median, 5.0);
  EXPECT_DOUBLE_EQ(rows[0].frame_ms.p10, 3.4);
  EXPECT_DOUBLE_EQ(rows[0].frame_ms.p90, 6.6);
  EXPECT_FALSE(rows[0].skipped);
  ASSERT_TRUE(rows[1].skipped.has_value());
  EXPECT_EQ(*rows[1].skipped, "no B-spline wedges");
  EXPECT_TRUE(std::isnan(rows[1].frame_ms.median));
  EXPECT_TRUE(std::any_of(notes.begin(), notes.end(), [](const std::string& n) {
    return n.find(" bspl") != std::string::npos && n.find("skipped on scripted: no B-spline wedges") != std::string::npos;
  })) << "the skip is reported";
}

// The sweeps' sizes (bench_sweep.h), and sweep settings that vary only what changes
// the sweep's horizons (W, K, lines; n and wedge after them) with s = 1: no two
// settings compute the same thing, and a march never lends its skyview to a sweep.
TEST(BenchSweeps, SweepSettingsVaryOnlyWhatChangesThem) {
  using namespace skylit::app::bench;
  using skylit::horizon::HorizonMethod;
  const skylit::horizon::MarchOptions d;
  EXPECT_EQ(sweep_settings("smoke").size(), 3u);
  EXPECT_EQ(sweep_settings("default").size(), 32u);
  EXPECT_EQ(sweep_settings("full").size(), 945u);
  for (const std::string name : {"default", "full"}) {
    const auto list = sweep_settings(name);
    int sweeps = 0;
    for (std::size_t a = 0; a < list.size(); ++a) {
      const BenchSetting& s = list[a];
      const auto o = options_for(s, 1);
      EXPECT_EQ(o.march.method, s.horizons);
      EXPECT_EQ(o.march.sweep_near_steps, s.near_steps);
      EXPECT_EQ(o.march.sweep_lines, s.sweep_lines);
      if (s.horizons == HorizonMethod::Sweep) {
        ++sweeps;
        EXPECT_EQ(s.subsample, 1) << s.label();  // the sweep does not sub-sample
        // Presets carry the march's knobs for the fields the sweep cannot take (high: k_v 8).
        EXPECT_TRUE(s.preset || (s.k_v == d.k_v && s.level_offset == d.level_offset && s.smooth_max == d.smooth_max &&
                                 s.levels == skylit::horizon::level_sampling(d)))
            << s.label();
        EXPECT_NE(s.label().find(" K" + std::to_string(s.near_steps) + " L" + std::to_string(s.sweep_lines)),
                  std::string::npos)
            << s.label();
      } else {
        EXPECT_TRUE(s.near_steps == d.sweep_near_steps && s.sweep_lines == d.sweep_lines) << s.label();
      }
      for (std::size_t b = 0; b < a; ++b) EXPECT_FALSE(list[b] == s) << name << ": " << s.label();
    }
    // default: the default preset (W 32, K 4, 1 line) with W (8, 16, 64), n (2, 3) or the
    // B-spline wedge changed, and (K, lines) = (2, 1), (4, 2), (8, 3) at W 32 and (2, 1),
    // (4, 1), (4, 2), (8, 3) at W 16 (W 16, K 4, 1 line counted above): 1 + 3 + 2 + 1 + 3 + 3
    // + 1 (high: k_v 8, K 8, 3 lines) + 1 (the highest corner: W 64, n 4, B-spline wedge,
    // K 8, 3 lines); full: the four (K, lines) × W × n × wedge, plus W × K ×
    // lines, the four counted once, plus high.
    EXPECT_EQ(sweeps, name == "default" ? 15 : 4 * 4 * 3 * 2 + 4 * 3 * 3 - 4 * 4 + 1) << name;
  }
  BenchSetting sweep = sweep_settings("smoke")[1], march = sweep;  // the default preset: a sweep
  ASSERT_EQ(sweep.horizons, HorizonMethod::Sweep);
  march.horizons = HorizonMethod::March;
  EXPECT_FALSE(march.same_march(sweep));
  BenchSetting more_lines = sweep;
  more_lines.sweep_lines = 2;
  EXPECT_FALSE(sweep.same_march(more_lines));

  BenchRow row{"s", "8", "reference", "wall", sweep, {1, 1, 1}, 1, {0, 0}, {0, 0}, std::nullopt};
  std::stringstream csv(csv_text({row}));
  std::string header, line;
  std::getline(csv, header);
  std::getline(csv, line);
  const auto columns = split(header, ','), cells = split(line, ',');
  ASSERT_EQ(cells.size(), columns.size());
  auto cell = [&](const std::string& c) { return cells[std::find(columns.begin(), columns.end(), c) - columns.begin()]; };
  EXPECT_EQ(cell("horizons"), "sweep");
  EXPECT_EQ(cell("near_steps"), std::to_string(d.sweep_near_steps));
  EXPECT_EQ(cell("sweep_lines"), std::to_string(d.sweep_lines));
}

TEST(GpuTimer, MissingWhenItReadsZeroAgainstTheWallClock) {
  using skylit::app::bench::FrameTime;
  const std::vector<FrameTime> llvmpipe = {{10, 10, 0.0}, {12, 12, 0.0}, {11, 11, 0.001}};
  const std::vector<FrameTime> device = {{10, 10, 2.0}, {12, 12, 2.5}, {11, 11, 2.2}};
  const std::vector<FrameTime> host_only = {{10, 10, std::nullopt}};
  EXPECT_TRUE(skylit::app::bench::gpu_timer_missing(llvmpipe));
  EXPECT_FALSE(skylit::app::bench::gpu_timer_missing(device));
  EXPECT_TRUE(skylit::app::bench::gpu_timer_missing(host_only));
}

TEST(QualityPresets, ParseApplyAndOrder) {
  using skylit::shading::Quality;
  EXPECT_EQ(skylit::shading::parse_quality("fast"), Quality::Fast);
  EXPECT_EQ(skylit::shading::parse_quality("high"), Quality::High);
  EXPECT_FALSE(skylit::shading::parse_quality("ultra").has_value());

  skylit::shading::ProductOptions defaults, o;
  o.march.max_distance_m = 1234.0;  // not a quality knob: left alone
  skylit::shading::apply_quality(Quality::Default, o);
  EXPECT_EQ(o.march.azimuths, defaults.march.azimuths);
  EXPECT_EQ(o.shaded.sh_order, defaults.shaded.sh_order);
  EXPECT_EQ(o.march.max_distance_m, 1234.0);
  // fast marches less than default, high at least as much (W · k_v steps per texel).
  auto march_cost = [](Quality q) {
    const auto s = skylit::shading::quality_settings(q);
    return s.azimuths * s.k_v;
  };
  EXPECT_LT(march_cost(Quality::Fast), march_cost(Quality::Default));
  EXPECT_LT(march_cost(Quality::Default), march_cost(Quality::High));
}

// Every knob a setting varies changes the horizons the renderer keeps and the pipeline
// it caches: a kept one must not serve a setting that differs in any of them (the
// bench's cache once ignored the horizon method).
TEST(BenchTiming, PipelinesDifferWhereSettingsDiffer) {
  using namespace skylit::app::bench;
  const auto list = sweep_settings("default");
  for (std::size_t a = 0; a < list.size(); ++a)
    for (std::size_t b = 0; b < list.size(); ++b)
      EXPECT_EQ(skylit::shading::same_horizon_options(options_for(list[a], 1), options_for(list[b], 1)), a == b)
          << list[a].label() << " vs " << list[b].label();
}

TEST(ParetoFront, KeepsOnlyUndominatedPointsFastestFirst) {
  // (ms, error): 1 is dominated by 0, 3 by 2; ties in time keep the lower error.
  const std::vector<skylit::app::bench::PlotPoint> points = {{10, 5}, {20, 6}, {30, 2}, {40, 2}, {30, 3}, {50, 1}};
  EXPECT_EQ(skylit::app::bench::pareto_front(points), (std::vector<std::size_t>{0, 2, 5}));
}

}  // namespace
