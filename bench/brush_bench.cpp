// Google Benchmark: one terrain brush application (terrain/brush.h), radius 200 m on a
// 1024² field with 1 m texels (≈ 126 000 texels under the disc), per mode. The field is
// built once; Raise and Lower alternate so heights stay bounded over many iterations.
//
//   build/bin/brush_bench
#include "terrain/brush.h"

#include <benchmark/benchmark.h>

namespace {

namespace tr = skylit::terrain;

void BM_Brush(benchmark::State& state) {
  const auto mode = static_cast<tr::BrushMode>(state.range(0));
  tr::HeightField f(1024, 1024, 1.0);
  for (int j = 0; j < f.height; ++j)  // some relief, so Smooth has work to do
    for (int i = 0; i < f.width; ++i) f.at(i, j) = static_cast<float>(((i * 7919 + j * 104729) % 1000) * 0.01);
  const double strength = mode == tr::BrushMode::Smooth ? 0.5 : 1.0;
  bool lower = false;
  for (auto _ : state) {
    const tr::BrushMode m = mode == tr::BrushMode::Smooth ? mode : (lower ? tr::BrushMode::Lower : tr::BrushMode::Raise);
    lower = !lower;
    benchmark::DoNotOptimize(tr::apply_brush(f, {m, 200.0, strength}, 512.0, -512.0));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Brush)->ArgName("mode")->Arg(0)->Arg(2)->Unit(benchmark::kMicrosecond);

}  // namespace
