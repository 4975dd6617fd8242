#include "app/bench/bench_sweep.h"

#include "shading/sh/sh_basis.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace skylit::app::bench {
namespace {

// The values each knob takes in the sweeps (the grid).
const std::vector<int> kAzimuths = {8, 16, 32, 64};
const std::vector<int> kKv = {2, 4, 8};
const std::vector<double> kLevelOffsets = {1, 2, 3};
const std::vector<int> kShOrders = {2, 3, 4};
const std::vector<int> kSubsamples = {4, 2, 1};  // cheapest first, like the others
using Wedge = sh::WedgeInterpolation;
const std::vector<Wedge> kWedges = {Wedge::Linear, Wedge::BSpline};
using Levels = horizon::LevelSampling;
const std::vector<Levels> kLevels = {Levels::None, Levels::Bilinear, Levels::BSpline};
const std::vector<bool> kSmoothMax = {false, true};
// The sweep's near steps K and lines per texel: crossed in the full sweep, and four
// settings along both, cheapest first, that the other sweeps take.
const std::vector<int> kNearSteps = {2, 4, 8};
const std::vector<int> kSweepLines = {1, 2, 3};
const std::vector<std::pair<int, int>> kSweeps = {{2, 1}, {4, 1}, {4, 2}, {8, 3}};  // (K, lines)

// A march; level sampling and maximum default to the library's (MarchOptions).
BenchSetting make_setting(int w, int k_v, double o_v, int n, int s, Wedge wedge,
                          Levels levels = horizon::level_sampling(horizon::MarchOptions{}),
                          bool smooth_max = horizon::MarchOptions{}.smooth_max) {
  const horizon::MarchOptions d;  // a march: the sweep knobs at their defaults
  return {w, k_v, o_v, n, 2 * n, s, wedge, levels, smooth_max, horizon::HorizonMethod::March, d.sweep_near_steps,
          d.sweep_lines, std::nullopt};
}

// A sweep with the march knobs at the defaults and s = 1 (BenchSetting: no duplicates).
BenchSetting sweep_setting(int w, int n, Wedge wedge, int near_steps, int lines) {
  const horizon::MarchOptions d;
  BenchSetting s = make_setting(w, d.k_v, d.level_offset, n, 1, wedge);
  s.horizons = horizon::HorizonMethod::Sweep;
  s.near_steps = near_steps;
  s.sweep_lines = lines;
  return s;
}

// Read back through apply_quality, so that every knob a preset sets is honoured.
BenchSetting preset_setting(shading::Quality q) {
  shading::ProductOptions o;
  shading::apply_quality(q, o);
  return {o.march.azimuths,         o.march.k_v,      o.march.level_offset,    o.shaded.sh_order,
          o.shaded.nlp_order,       o.subsample,      o.shaded.wedge,          horizon::level_sampling(o.march),
          o.march.smooth_max,       o.march.method,   o.march.sweep_near_steps, o.march.sweep_lines,
          q};
}

// Appends s unless an equal setting is already there.
void add_unique(std::vector<BenchSetting>& list, const BenchSetting& s) {
  if (std::find(list.begin(), list.end(), s) == list.end()) list.push_back(s);
}

BenchSetting lowest() {
  return make_setting(kAzimuths.front(), kKv.front(), kLevelOffsets.front(), kShOrders.front(), kSubsamples.front(),
                      kWedges.front(), kLevels.front(), kSmoothMax.front());
}
// The sweep at its most: the sweep beats every march on the fields it applies to.
BenchSetting highest() {
  return sweep_setting(kAzimuths.back(), kShOrders.back(), kWedges.back(), kNearSteps.back(), kSweepLines.back());
}

std::vector<BenchSetting> default_sweep() {
  // The default preset (a sweep) and the march at its defaults, each with one knob
  // changed: W, n and wedge on both; the pyramid knobs and s on the march only (the
  // sweep ignores them); K and lines on the sweep at the fast and default W.
  const BenchSetting d = preset_setting(shading::Quality::Default);
  const BenchSetting dm = make_setting(d.azimuths, d.k_v, d.level_offset, d.sh_order, d.subsample, d.wedge, d.levels,
                                 d.smooth_max);
  std::vector<BenchSetting> list = {lowest(), d, dm};
  // base with one knob changed; N = 2n as in the grid.
  auto around = [&](const BenchSetting& base, auto change) {
    BenchSetting s = base;
    change(s);
    s.nlp_order = 2 * s.sh_order;
    s.preset.reset();
    add_unique(list, s);
  };
  for (const BenchSetting* base : {&d, &dm}) {
    for (int w : kAzimuths) around(*base, [&](BenchSetting& s) { s.azimuths = w; });
    for (int n : kShOrders) around(*base, [&](BenchSetting& s) { s.sh_order = n; });
    for (Wedge e : kWedges) around(*base, [&](BenchSetting& s) { s.wedge = e; });
  }
  for (int k : kKv) around(dm, [&](BenchSetting& s) { s.k_v = k; });
  for (double o : kLevelOffsets) around(dm, [&](BenchSetting& s) { s.level_offset = o; });
  for (int sub : kSubsamples) around(dm, [&](BenchSetting& s) { s.subsample = sub; });
  for (Levels l : kLevels) around(dm, [&](BenchSetting& s) { s.levels = l; });
  for (bool m : kSmoothMax) around(dm, [&](BenchSetting& s) { s.smooth_max = m; });
  for (int w : {preset_setting(shading::Quality::Fast).azimuths, d.azimuths})  // the fast and default W
    for (auto [k, lines] : kSweeps) add_unique(list, sweep_setting(w, d.sh_order, d.wedge, k, lines));
  add_unique(list, highest());
  return list;
}

std::vector<BenchSetting> full_sweep() {
  std::vector<BenchSetting> list;
  for (int w : kAzimuths)
    for (int k : kKv)
      for (double o : kLevelOffsets)
        for (int n : kShOrders)
          for (int s : kSubsamples)
            for (Wedge e : kWedges) list.push_back(make_setting(w, k, o, n, s, e));
  // The march knobs crossed with each other at the default n, s and wedge.
  const BenchSetting d = preset_setting(shading::Quality::Default);
  for (int w : kAzimuths)
    for (int k : kKv)
      for (double o : kLevelOffsets)
        for (Levels l : kLevels)
          for (bool m : kSmoothMax) add_unique(list, make_setting(w, k, o, d.sh_order, d.subsample, d.wedge, l, m));
  // The sweep ignores the pyramid knobs: the four sweeps (kSweeps) crossed with W, n and wedge,
  // and every (W, K, lines) at the default n and wedge.
  for (int w : kAzimuths)
    for (int n : kShOrders)
      for (Wedge e : kWedges)
        for (auto [k, lines] : kSweeps) add_unique(list, sweep_setting(w, n, e, k, lines));
  for (int w : kAzimuths)
    for (int k : kNearSteps)
      for (int lines : kSweepLines) add_unique(list, sweep_setting(w, d.sh_order, d.wedge, k, lines));
  return list;
}

// Tags settings equal to a preset, and adds the presets the sweep does not hold.
void include_presets(std::vector<BenchSetting>& list) {
  for (shading::Quality q : shading::all_qualities()) {
    const BenchSetting p = preset_setting(q);
    const auto it = std::find(list.begin(), list.end(), p);
    if (it != list.end()) it->preset = q;
    else list.push_back(p);
  }
}

double percentile(const std::vector<double>& sorted, double p) {
  const double pos = p * static_cast<double>(sorted.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(pos));
  const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
  return sorted[lo] + (pos - static_cast<double>(lo)) * (sorted[hi] - sorted[lo]);
}

}  // namespace

std::string BenchSetting::label() const {
  std::ostringstream s;
  s << 'W' << azimuths << " kv" << k_v << " o" << level_offset << " n" << sh_order;
  if (nlp_order != 2 * sh_order) s << " N" << nlp_order;
  if (subsample != 1) s << " s" << subsample;
  if (wedge == sh::WedgeInterpolation::BSpline) s << " bspl";
  const horizon::MarchOptions defaults;
  if (levels != horizon::level_sampling(defaults)) s << ' ' << horizon::level_sampling_name(levels);
  if (smooth_max != defaults.smooth_max) s << ' ' << horizon::horizon_max_name(smooth_max);
  if (horizons != defaults.method) s << ' ' << horizon::horizon_method_name(horizons);
  if (horizons == horizon::HorizonMethod::Sweep) s << " K" << near_steps << " L" << sweep_lines;
  return s.str();
}

std::string_view wedge_name(sh::WedgeInterpolation w) {
  return w == sh::WedgeInterpolation::BSpline ? "bspline" : "linear";
}

std::vector<std::string> sweep_names() { return {"smoke", "default", "full"}; }

std::vector<BenchSetting> sweep_settings(std::string_view name) {
  if (name == "smoke") {
    std::vector<BenchSetting> list = {lowest(), preset_setting(shading::Quality::Default), highest()};
    for (auto& s : list)  // tag, but add nothing: the smoke test counts its rows
      for (shading::Quality q : shading::all_qualities())
        if (s == preset_setting(q)) s.preset = q;
    return list;
  }
  std::vector<BenchSetting> list;
  if (name == "default") list = default_sweep();
  else if (name == "full") list = full_sweep();
  else throw std::invalid_argument("unknown --sweep '" + std::string(name) + "' (smoke, default, full)");
  include_presets(list);
  return list;
}

shading::ProductOptions options_for(const BenchSetting& s, unsigned threads) {
  shading::ProductOptions o;
  o.march.azimuths = s.azimuths;
  o.march.k_v = s.k_v;
  o.march.level_offset = s.level_offset;
  o.shaded.sh_order = s.sh_order;
  o.shaded.nlp_order = s.nlp_order;
  o.shaded.wedge = s.wedge;
  horizon::set_level_sampling(o.march, s.levels);
  o.march.smooth_max = s.smooth_max;
  o.march.method = s.horizons;
  o.march.sweep_near_steps = s.near_steps;
  o.march.sweep_lines = s.sweep_lines;
  o.subsample = s.subsample;
  o.threads = threads;
  return o;
}

shading::ProductOptions truth_options(unsigned threads) {
  shading::ProductOptions o;
  o.exact = true;
  o.shaded.sh_order = sh::kMaxOrder;
  o.shaded.nlp_order = 2 * sh::kMaxOrder;
  o.threads = threads;
  return o;
}

TimeStats time_stats(std::vector<double> samples_ms) {
  if (samples_ms.empty()) throw std::invalid_argument("time_stats: no samples");
  std::sort(samples_ms.begin(), samples_ms.end());
  return {percentile(samples_ms, 0.5), percentile(samples_ms, 0.1), percentile(samples_ms, 0.9)};
}

ErrorStats error_stats(const shading::ProductBands& value, const shading::ProductBands& truth) {
  if (value.data.size() != truth.data.size()) throw std::logic_error("error_stats: band sizes differ");
  double sum2 = 0, max = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < value.data.size(); ++i) {
    const double v = value.data[i], t = truth.data[i];
    if (!std::isfinite(v) || !std::isfinite(t)) continue;
    sum2 += (v - t) * (v - t);
    max = std::max(max, std::abs(v - t));
    ++count;
  }
  if (count == 0) return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  return {std::sqrt(sum2 / static_cast<double>(count)), max};
}

}  // namespace skylit::app::bench
