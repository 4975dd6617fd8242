// Google Benchmark: horizon marching and whole products of the CPU reference on the
// synthetic scene (terrain/synthetic.h, 30 m texels, seed 1) — docs/performance.md.
//
//  * BM_MaxElevation: HorizonMarcher::max_elevation, one texel × one azimuth per call
//    (W = 32 headings), walking the texels row by row as compute_product does
//    (random:0) or cycling over 4096 scattered (texel, azimuth) pairs (random:1, cache
//    cold). items_per_second = texel·azimuths per second. Variants: B-spline max on/off,
//    pyramid on/off (off = every step bilinear on level 0).
//  * BM_ExactMaxElevation: the ground-truth march (half-texel steps, bilinear) per call.
//  * BM_MarcherBuild: the pyramid build a HorizonMarcher does once per DEM.
//  * BM_ComputeProduct: compute_product (svf / skyview / shaded) on 256² (1 and 2
//    threads) and 512² (2 threads; 1 thread for svf only, to keep the run short). One
//    iteration each; "Time" is wall time, "CPU" is the whole process's CPU time (all
//    threads, MeasureProcessCPUTime) and the rates are per CPU second, so they compare
//    across thread counts and stay meaningful when the machine is loaded. The default
//    march (method march), W = 32 (exact: W = ExactOptions::sky_azimuths = 360).
//  * BM_ComputeProductSweep: the same products with the horizon sweep (2 threads).
//  * BM_SweepFarSlopes: horizon::sweep_far_slopes for one heading, on 1 or every thread
//    (threads: 0; wall time, as UseRealTime).
//  * BM_ComputeProductExact: the same with exact = true on a small 64² scene (the dense
//    ground truth costs more per texel·azimuth and uses 360 azimuths), next to the
//    default march on the same scene.
//
// Whole run ≈ 1.5–2 min on 2 idle cores: build/bin/march_bench
// Kernels only:                       build/bin/march_bench --benchmark_filter=Elevation
#include "shading/horizon/azimuth.h"
#include "shading/horizon/horizon_exact.h"
#include "shading/horizon/horizon_march.h"
#include "shading/horizon/horizon_sweep.h"
#include "shading/products.h"
#include "shading/sun_light.h"
#include "terrain/height_field.h"
#include "terrain/pyramid.h"
#include "terrain/synthetic.h"

#include <benchmark/benchmark.h>

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

namespace {

namespace horizon = skylit::horizon;
namespace shading = skylit::shading;
namespace tr = skylit::terrain;

constexpr int kAzimuths = 32;

// One synthetic field per size, built once and kept for the program's life.
const tr::HeightField& scene(int size) {
  static std::mutex mu;
  static std::map<int, std::unique_ptr<tr::HeightField>> cache;
  std::lock_guard lock(mu);
  auto& slot = cache[size];
  if (!slot) {
    tr::SyntheticOptions o;
    o.width = o.height = size;
    slot = std::make_unique<tr::HeightField>(tr::make_synthetic_terrain(o));
  }
  return *slot;
}

struct Sample {
  int i, j;
  horizon::Heading u;
};

// 4096 (texel, azimuth) pairs, uniform over the grid and the W headings.
std::vector<Sample> samples(int size) {
  std::mt19937_64 rng(42);
  std::vector<Sample> s(4096);
  for (auto& x : s) {
    x.i = static_cast<int>(rng() % size);
    x.j = static_cast<int>(rng() % size);
    const int k = static_cast<int>(rng() % kAzimuths);
    x.u = horizon::heading_from_geographic(horizon::band_azimuth(k, kAzimuths));
  }
  return s;
}

// ---- per texel · azimuth ----------------------------------------------------------------

// Coherent order (as compute_product walks): texels row by row, the W azimuths of a
// texel in turn. Random order: the 4096 scattered pairs (cache-cold samples).
void BM_MaxElevation(benchmark::State& state) {
  const int size = static_cast<int>(state.range(0));
  horizon::MarchOptions opt;
  opt.azimuths = kAzimuths;
  opt.smooth_max = state.range(1) != 0;
  opt.use_pyramid = state.range(2) != 0;
  const bool random = state.range(3) != 0;
  const tr::HeightField& field = scene(size);
  const horizon::HorizonMarcher marcher(field, opt);
  const auto s = samples(size);
  std::vector<horizon::Heading> headings(kAzimuths);
  for (int k = 0; k < kAzimuths; ++k)
    headings[k] = horizon::heading_from_geographic(horizon::band_azimuth(k, kAzimuths));
  std::size_t r = 0;
  int i = 0, j = size / 4, k = 0;  // start a quarter down: rows near the edge end early
  for (auto _ : state) {
    double e;
    if (random) {
      const Sample& x = s[r];
      r = (r + 1) & (s.size() - 1);
      e = marcher.max_elevation(x.i, x.j, x.u);
    } else {
      e = marcher.max_elevation(i, j, headings[k]);
      if (++k == kAzimuths) {
        k = 0;
        if (++i == size) {
          i = 0;
          if (++j == size) j = 0;
        }
      }
    }
    benchmark::DoNotOptimize(e);
  }
  state.SetItemsProcessed(state.iterations());  // texel·azimuths
  state.counters["steps"] = marcher.steps();
}
BENCHMARK(BM_MaxElevation)
    ->ArgNames({"size", "smooth", "pyramid", "random"})
    ->Args({256, 1, 1, 0})
    ->Args({512, 1, 1, 0})
    ->Args({1024, 1, 1, 0})
    ->Args({512, 1, 1, 1})
    ->Args({1024, 1, 1, 1})
    ->Args({512, 0, 1, 0})
    ->Args({512, 1, 0, 0})
    ->MinTime(0.3);

void BM_ExactMaxElevation(benchmark::State& state) {
  const int size = static_cast<int>(state.range(0));
  const tr::HeightField& field = scene(size);
  const horizon::ExactMarch opt;
  const auto s = samples(size);
  std::size_t k = 0;
  for (auto _ : state) {
    const Sample& x = s[k];
    k = (k + 1) & (s.size() - 1);
    double e = horizon::exact_max_elevation(field, x.i, x.j, x.u, opt);
    benchmark::DoNotOptimize(e);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ExactMaxElevation)->ArgName("size")->Arg(256)->Arg(512)->Unit(benchmark::kMicrosecond)->MinTime(0.3);

// ---- one-off per DEM -------------------------------------------------------------------

void BM_MarcherBuild(benchmark::State& state) {
  const tr::HeightField& field = scene(static_cast<int>(state.range(0)));
  horizon::MarchOptions opt;
  opt.azimuths = kAzimuths;
  for (auto _ : state) {
    horizon::HorizonMarcher marcher(field, opt);
    benchmark::DoNotOptimize(&marcher);
  }
  state.SetItemsProcessed(state.iterations() * field.width * field.height);  // texels/s
}
BENCHMARK(BM_MarcherBuild)->ArgName("size")->Arg(512)->Arg(1024)->Unit(benchmark::kMillisecond)->MinTime(0.3);

// ---- whole products --------------------------------------------------------------------

const shading::Product kProducts[] = {shading::Product::Svf, shading::Product::Skyview, shading::Product::Shaded};

void run_product(benchmark::State& state, int size, shading::Product product, unsigned threads, bool exact,
                 horizon::HorizonMethod method = horizon::HorizonMethod::March) {
  const tr::HeightField& field = scene(size);
  shading::ProductOptions opt;
  opt.march.method = method;
  opt.march.azimuths = kAzimuths;
  opt.threads = threads;
  opt.exact = exact;
  for (auto _ : state) {
    shading::ProductBands bands = shading::compute_product(field, product, opt);
    benchmark::DoNotOptimize(bands.data.data());
  }
  const double texels = static_cast<double>(field.width) * field.height;
  const int azimuths = exact ? opt.exact_options.sky_azimuths : opt.march.azimuths;
  // Rates per second of process CPU time (all threads): comparable across thread counts.
  state.counters["texels/s"] = benchmark::Counter(texels * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["texel_az/s"] =
      benchmark::Counter(texels * azimuths * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["W"] = azimuths;
  state.SetLabel(std::string(shading::product_name(product)));
}

void BM_ComputeProduct(benchmark::State& state) {
  run_product(state, static_cast<int>(state.range(0)), kProducts[state.range(1)],
              static_cast<unsigned>(state.range(2)), false);
}
BENCHMARK(BM_ComputeProduct)
    ->ArgNames({"size", "product", "threads"})
    ->ArgsProduct({{256}, {0, 1, 2}, {1, 2}})
    ->ArgsProduct({{512}, {0, 1, 2}, {2}})
    ->Args({512, 0, 1})  // 512² single-threaded: svf only (the march dominates all three)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->Iterations(1);

// The same products with the horizon sweep (the default on projected grids), 2 threads.
void BM_ComputeProductSweep(benchmark::State& state) {
  run_product(state, static_cast<int>(state.range(0)), kProducts[state.range(1)], 2, false,
              horizon::HorizonMethod::Sweep);
}
BENCHMARK(BM_ComputeProductSweep)
    ->ArgNames({"size", "product"})
    ->ArgsProduct({{256, 512}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->Iterations(1);

// sweep_far_slopes for one heading (30° off the x axis), one thread: the sweep's cost per
// azimuth. items_per_second = texels per second.
void BM_SweepFarSlopes(benchmark::State& state) {
  const tr::HeightField& field = scene(static_cast<int>(state.range(0)));
  horizon::MarchOptions o;
  o.sweep_near_steps = static_cast<int>(state.range(1));
  o.sweep_lines = static_cast<int>(state.range(2));
  const horizon::Heading u = horizon::heading_from_geographic(horizon::band_azimuth(1, 12));
  const unsigned threads = static_cast<unsigned>(state.range(3));
  for (auto _ : state) benchmark::DoNotOptimize(horizon::sweep_far_slopes(field, u, o, threads).data());
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(field.size()));
}
BENCHMARK(BM_SweepFarSlopes)
    ->ArgNames({"size", "K", "lines", "threads"})
    ->ArgsProduct({{256, 1024}, {4}, {1, 2}, {1, 0}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

// The same within a maximum distance of 3 km (100 texels of 30 m), one thread: the
// tiles' sweep (a window of two hulls, horizon_sweep.h), whose cost is per observer.
void BM_SweepFarSlopesBounded(benchmark::State& state) {
  const tr::HeightField& field = scene(static_cast<int>(state.range(0)));
  horizon::MarchOptions o;
  o.max_distance_m = 3000.0;
  const horizon::Heading u = horizon::heading_from_geographic(horizon::band_azimuth(1, 12));
  for (auto _ : state) benchmark::DoNotOptimize(horizon::sweep_far_slopes(field, u, o, 1).data());
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(field.size()));
}
BENCHMARK(BM_SweepFarSlopesBounded)->ArgNames({"size"})->Arg(1024)->UseRealTime()->Unit(benchmark::kMillisecond);

// The sun's sweep (K 8, 3 lines, shading::sun_march_options) with the floor of a sun
// at `elevation` degrees (shading::sun_sweep_floor: none below 30°), one thread, 1024²:
// what the floor saves by the sun's height.
void BM_SunSweepFloor(benchmark::State& state) {
  const tr::HeightField& field = scene(1024);
  const shading::SunShadowOptions sun;
  const horizon::Heading u = horizon::heading_from_geographic(horizon::band_azimuth(1, 12));
  const double elevation = static_cast<double>(state.range(0)) * std::numbers::pi / 180.0;
  const double floor = shading::sun_sweep_floor(elevation, sun);
  for (auto _ : state) benchmark::DoNotOptimize(horizon::sweep_far_slopes(field, u, sun.march, 1, floor).data());
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(field.size()));
}
BENCHMARK(BM_SunSweepFloor)->ArgNames({"elevation"})->DenseRange(0, 60, 10)->Arg(89)->UseRealTime()->Unit(benchmark::kMillisecond);

// exact = true vs the default march, 64² (see the header comment).
void BM_ComputeProductExact(benchmark::State& state) {
  run_product(state, 64, kProducts[state.range(0)], 2, state.range(1) != 0);
}
BENCHMARK(BM_ComputeProductExact)
    ->ArgNames({"product", "exact"})
    ->ArgsProduct({{0, 1, 2}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->Iterations(1);

}  // namespace
