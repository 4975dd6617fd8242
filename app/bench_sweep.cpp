#include "app/bench_sweep.h"

#include "app/backend.h"
#include "shading/sh_basis.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <time.h>
#include <stdexcept>

namespace skylit::app {
namespace {

// The values each knob takes in the sweeps (the grid).
const std::vector<int> kAzimuths = {8, 16, 32, 64};
const std::vector<int> kKv = {2, 4, 8};
const std::vector<double> kLevelOffsets = {1, 2, 3};
const std::vector<int> kShOrders = {2, 3, 4};

BenchSetting make_setting(int w, int k_v, double o_v, int n) { return {w, k_v, o_v, n, 2 * n, std::nullopt}; }

BenchSetting preset_setting(shading::Quality q) {
  const shading::QualitySettings s = shading::quality_settings(q);
  return {s.azimuths, s.k_v, s.level_offset, s.sh_order, s.nlp_order, q};
}

// Appends s unless an equal setting is already there.
void add_unique(std::vector<BenchSetting>& list, const BenchSetting& s) {
  if (std::find(list.begin(), list.end(), s) == list.end()) list.push_back(s);
}

BenchSetting lowest() { return make_setting(kAzimuths.front(), kKv.front(), kLevelOffsets.front(), kShOrders.front()); }
BenchSetting highest() { return make_setting(kAzimuths.back(), kKv.back(), kLevelOffsets.back(), kShOrders.back()); }

std::vector<BenchSetting> default_sweep() {
  const BenchSetting d = preset_setting(shading::Quality::Default);
  std::vector<BenchSetting> list = {lowest()};
  for (int w : kAzimuths) add_unique(list, make_setting(w, d.k_v, d.level_offset, d.sh_order));
  for (int k : kKv) add_unique(list, make_setting(d.azimuths, k, d.level_offset, d.sh_order));
  for (double o : kLevelOffsets) add_unique(list, make_setting(d.azimuths, d.k_v, o, d.sh_order));
  for (int n : kShOrders) add_unique(list, make_setting(d.azimuths, d.k_v, d.level_offset, n));
  add_unique(list, highest());
  return list;
}

std::vector<BenchSetting> full_sweep() {
  std::vector<BenchSetting> list;
  for (int w : kAzimuths)
    for (int k : kKv)
      for (double o : kLevelOffsets)
        for (int n : kShOrders) list.push_back(make_setting(w, k, o, n));
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

// Milliseconds on CLOCK_PROCESS_CPUTIME_ID: every thread of the process.
double process_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}
double wall_ms() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Times compute_with_backend between two readings of a host clock.
class HostClockSource final : public TimingSource {
 public:
  HostClockSource(std::string backend, bool cpu) : backend_(std::move(backend)), cpu_(cpu) {}
  std::string_view clock() const override { return cpu_ ? kCpuClock : kWallClock; }
  shading::ProductBands compute(const terrain::HeightField& field, shading::Product product,
                                const shading::ProductOptions& options, double& ms) override {
    const double start = now();
    auto bands = compute_with_backend(backend_, field, product, options, {});
    ms = now() - start;
    return bands;
  }

 private:
  double now() const { return cpu_ ? process_cpu_ms() : wall_ms(); }
  std::string backend_;
  bool cpu_;
};

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& n : names) text += (text.empty() ? "" : ", ") + n;
  return text;
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
  return s.str();
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

std::vector<std::string> clock_names() { return {std::string(kWallClock), std::string(kCpuClock)}; }

std::unique_ptr<TimingSource> make_timing_source(const std::string& backend, const std::string& clock) {
  const auto backends = backend_names(), clocks = clock_names();
  if (std::find(backends.begin(), backends.end(), backend) == backends.end())
    throw std::invalid_argument("unknown --backend '" + backend + "' (" + joined(backends) + ")");
  if (std::find(clocks.begin(), clocks.end(), clock) == clocks.end())
    throw std::invalid_argument("unknown --clock '" + clock + "' (" + joined(clocks) + ")");
  return std::make_unique<HostClockSource>(backend, clock == kCpuClock);
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

}  // namespace skylit::app
