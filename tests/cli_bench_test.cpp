// `skylit bench` end to end on a tiny scene: CSV layout, finite errors that fall from
// the lowest to the highest quality setting, a valid SVG with the Pareto front, and
// one-line errors that leave no files for bad arguments.
#include "cli_test_util.h"

#include "app/svg_plot.h"
#include "shading/quality.h"

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
            "scene,size,backend,azimuths,k_v,level_offset,sh_order,nlp_order,preset,clock,"
            "ms_median,ms_p10,ms_p90,skyview_rmse,skyview_max,shaded_rmse,shaded_max");
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
    EXPECT_GT(std::stod(row[col("ms_median")]), 0.0);
    EXPECT_LE(std::stod(row[col("ms_p10")]), std::stod(row[col("ms_median")]));
    EXPECT_LE(std::stod(row[col("ms_median")]), std::stod(row[col("ms_p90")]));
    for (const char* e : {"skyview_rmse", "skyview_max", "shaded_rmse", "shaded_max"}) {
      const double v = std::stod(row[col(e)]);
      EXPECT_TRUE(std::isfinite(v) && v >= 0.0) << e << " = " << row[col(e)];
    }
  }
  // The smoke sweep runs lowest → default → highest: a real check of the front.
  EXPECT_EQ(rows[0][col("azimuths")], "8");
  EXPECT_EQ(rows[2][col("azimuths")], "64");
  EXPECT_EQ(rows[1][col("preset")], "default");
  for (const char* e : {"skyview_rmse", "shaded_rmse"}) {
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

TEST(ParetoFront, KeepsOnlyUndominatedPointsFastestFirst) {
  // (ms, error): 1 is dominated by 0, 3 by 2; ties in time keep the lower error.
  const std::vector<skylit::app::PlotPoint> points = {{10, 5}, {20, 6}, {30, 2}, {40, 2}, {30, 3}, {50, 1}};
  EXPECT_EQ(skylit::app::pareto_front(points), (std::vector<std::size_t>{0, 2, 5}));
}

}  // namespace
