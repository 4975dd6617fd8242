// `skylit shade --horizons march|sweep`, --near-steps and --sweep-lines end to end on
// the reference backend (the GPU pipeline decides for itself): the sweep runs where it
// applies, explicit flags win over presets, one note says why the march runs instead
// elsewhere, and bad values fail cleanly.
#include "cli_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using skylit::testing::expect_clean_shade_failure;
using skylit::testing::read_output;
using skylit::testing::run_skylit;
using namespace skylit::terrain::testing;

namespace {

// A 24×20 rough DEM (a hill plus a hashed bumpiness, so that rays of neighbouring
// lines see different heights), 30 m pixels: projected (UTM 11N) or geographic.
// Projected (UTM), geographic at 46° N, or geographic from 88.9° to 86.0° N (row spacings
// 3.4× apart: nearer a pole than the sweep takes).
enum class Grid { Projected, Geographic, NearPole };
std::string make_dem(const ScratchDir& dir, Grid grid) {
  RasterSpec s;
  s.width = 24;
  s.height = 20;
  for (int j = 0; j < 20; ++j)
    for (int i = 0; i < 24; ++i)
      s.values.push_back(500 + 300 * std::exp(-((i - 12) * (i - 12) + (j - 10) * (j - 10)) / 20.0) +
                         ((i * 7919 + j * 104729) % 97));
  if (grid != Grid::Projected) s.epsg = 4326;
  if (grid == Grid::Geographic) s.gt = {-120.0, 0.0003, 0, 46.0, 0, -0.0003};
  if (grid == Grid::NearPole) s.gt = {-120.0, 0.1, 0, 88.9, 0, -0.145};
  const char* names[] = {"utm.tif", "geo.tif", "polar.tif"};
  return make_raster(dir.file(names[static_cast<int>(grid)]), s);
}

struct Shade {
  std::vector<float> v;  // horizon bands (degrees)
  std::string log;       // stdout and stderr
};

Shade shade(const ScratchDir& dir, const std::string& in, const std::string& extra) {
  const std::string out = dir.file("h.tif");
  const auto r = run_skylit(
      "shade " + in + " -o " + out + " -p horizon --azimuths 8 --backend reference --overwrite " + extra, true);
  EXPECT_EQ(r.status, 0) << extra << "\n" << r.out;
  return {read_output(out).v, r.out};
}

int notes(const std::string& log) {
  int n = 0;
  for (std::size_t at = log.find("skylit: note:"); at != std::string::npos; at = log.find("skylit: note:", at + 1)) ++n;
  return n;
}

TEST(CliHorizons, SweepRunsWhereItAppliesAndExplicitFlagsWin) {
  ScratchDir dir;
  const std::string in = make_dem(dir, Grid::Projected);
  const Shade march = shade(dir, in, "--horizons march"), sweep = shade(dir, in, "--horizons sweep");
  EXPECT_EQ(notes(sweep.log), 0) << sweep.log;
  EXPECT_NE(march.v, sweep.v);
  EXPECT_EQ(sweep.v, shade(dir, in, "").v);  // the default is the sweep
  // K ≥ twice the side: every sample is a near step, i.e. the exact march.
  EXPECT_EQ(shade(dir, in, "--horizons sweep --near-steps 48").v, shade(dir, in, "--exact").v);
  // The knobs reach the sweep, and presets keep the sweep and its knobs when asked.
  EXPECT_NE(sweep.v, shade(dir, in, "--horizons sweep --near-steps 0 --sweep-lines 1").v);
  EXPECT_EQ(shade(dir, in, "--quality high --horizons sweep --near-steps 0 --sweep-lines 1").v,
            shade(dir, in, "--horizons sweep --near-steps 0 --sweep-lines 1").v);  // W set by --azimuths
}

TEST(CliHorizons, OneNoteSaysWhyTheMarchRunsInstead) {
  ScratchDir dir;
  const std::string utm = make_dem(dir, Grid::Projected), polar = make_dem(dir, Grid::NearPole);
  struct Case {
    std::string in, extra, why;
  };
  for (const Case& c : {Case{polar, "", "near a pole"}, Case{utm, "--max-distance 100", "near steps"},
                        Case{utm, "--exact", "exact march"}}) {
    const Shade s = shade(dir, c.in, "--horizons sweep " + c.extra);
    EXPECT_EQ(notes(s.log), 1) << c.extra << "\n" << s.log;
    EXPECT_NE(s.log.find(c.why), std::string::npos) << s.log;
    EXPECT_EQ(s.v, shade(dir, c.in, "--horizons march " + c.extra).v) << c.extra;  // what runs instead
    EXPECT_EQ(notes(shade(dir, c.in, c.extra).log), 0) << c.extra;  // the default sweep falls back quietly
  }
  EXPECT_EQ(notes(shade(dir, utm, "--horizons sweep -q").log), 0);
  EXPECT_EQ(notes(shade(dir, polar, "--horizons march").log), 0);  // no sweep asked for
  // Sub-sampling sweeps the coarse texels: no note, not the march.
  const Shade sub = shade(dir, utm, "--horizons sweep --subsample 2");
  EXPECT_EQ(notes(sub.log), 0) << sub.log;
  EXPECT_NE(sub.v, shade(dir, utm, "--horizons march --subsample 2").v);
  EXPECT_NE(sub.v, shade(dir, utm, "--horizons sweep").v);
  // A bounded search beyond the near steps (5 half texels, ≤ 106 m here) sweeps within it.
  const Shade bounded = shade(dir, utm, "--horizons sweep --max-distance 300");
  EXPECT_EQ(notes(bounded.log), 0) << bounded.log;
  EXPECT_NE(bounded.v, shade(dir, utm, "--horizons march --max-distance 300").v);
  EXPECT_NE(bounded.v, shade(dir, utm, "--horizons sweep").v);
  // A geographic grid at 46° N sweeps along its rhumb lines: no note, not the march.
  const std::string geo = make_dem(dir, Grid::Geographic);
  const Shade swept = shade(dir, geo, "--horizons sweep");
  EXPECT_EQ(notes(swept.log), 0) << swept.log;
  EXPECT_NE(swept.v, shade(dir, geo, "--horizons march").v);
  EXPECT_EQ(swept.v, shade(dir, geo, "").v);
}

TEST(CliHorizons, BadValuesFailCleanly) {
  ScratchDir dir;
  const std::string in = make_dem(dir, Grid::Projected) + " -o " + dir.file("x.tif");
  expect_clean_shade_failure(dir, in + " --horizons spiral", "--horizons");
  expect_clean_shade_failure(dir, in + " --sweep-lines 0", "--sweep-lines");
  expect_clean_shade_failure(dir, in + " --near-steps -1", "--near-steps");
}

}  // namespace
