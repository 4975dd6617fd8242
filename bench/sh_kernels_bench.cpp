// Google Benchmark: the per-texel SH kernels of the CPU reference (docs/performance.md).
//
//  * exp_hyb<float/double>: HYB exponentiation, orders 2..8, log vectors of 1/10/100
//    overlapping spheres (the exp_report scene: centres in a 35° cone, d ∈ [1.5, 6],
//    r/d ∈ [0.15, 0.6]); default HybOptions (PS2 base, guards on).
//  * accumulate_log_visibility: 1/10/100 spheres into an order-4 / order-8 log vector.
//  * truncated product (TripleProduct::product and truncated_product<T>), orders 2..8.
//  * WedgeOperator::assemble and visibility_from_horizon: W = 16/32/64, N = 4/8,
//    linear / B-spline, SH order 4 (the `shaded` default).
//  * NLP slices (visibility, log-visibility) for N = 4/8/16.
//  * SH rotation: rotate_z_inplace, add_rotated_zh, ShRotation build and apply.
//
// Each benchmark processes one call per iteration: the reported time is ns per call.
// Run all (≈ 1–2 min on 2 cores): build/bin/sh_kernels_bench
// One family:                       build/bin/sh_kernels_bench --benchmark_filter=ExpHyb
#include "shading/blockers/sphere_blocker.h"
#include "shading/sh/nlp.h"
#include "shading/sh/sh_basis.h"
#include "shading/sh/sh_exp.h"
#include "shading/sh/sh_product.h"
#include "shading/sh/sh_rotation.h"
#include "shading/sh/wedge.h"

#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace {

namespace sh = skylit::sh;
namespace blockers = skylit::blockers;
using sh::kPi;

const glm::dvec3 kOrigin{0.0, 0.0, 0.0};
const glm::dvec3 kUp{0.0, 0.0, 1.0};

double uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1p-53; }

// Same distribution as bench/exp_report.cpp (math-notes §6.3).
std::vector<blockers::Sphere> make_spheres(int count, std::uint64_t seed = 1000) {
  std::mt19937_64 rng(seed + static_cast<std::uint64_t>(count));
  std::vector<blockers::Sphere> spheres;
  const double cone = 35.0 * kPi / 180;
  for (int i = 0; i < count; ++i) {
    const double cz = 1 - uniform(rng) * (1 - std::cos(cone)), phi = 2 * kPi * uniform(rng);
    const double rz = std::sqrt(1 - cz * cz), d = 1.5 + 4.5 * uniform(rng), ratio = 0.15 + 0.45 * uniform(rng);
    spheres.push_back({d * glm::dvec3(rz * std::cos(phi), rz * std::sin(phi), cz), ratio * d});
  }
  return spheres;
}

sh::Vec log_vector(int order, int count) {
  sh::Vec f(sh::num_coeffs(order), 0.0);
  blockers::accumulate_log_visibility(make_spheres(count), kOrigin, kUp, blockers::BlockerOptions{}, f);
  return f;
}

// Smooth random SH vector with a dominant DC (a plausible visibility / radiance).
sh::Vec random_vector(int order, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  sh::Vec v(sh::num_coeffs(order));
  for (int i = 0; i < sh::num_coeffs(order); ++i)
    v[i] = (2 * uniform(rng) - 1) / (1 + sh::band_of(i));
  v[0] = 2.0;
  return v;
}

// Horizon elevations of a rugged site: 0..35° with a few ridges.
std::vector<double> make_horizon(int w) {
  std::vector<double> sigma(w);
  for (int j = 0; j < w; ++j) {
    const double phi = 2 * kPi * j / w;
    sigma[j] = (12.0 + 8.0 * std::sin(3 * phi) + 6.0 * std::cos(7 * phi + 0.4) + 5.0 * std::sin(phi)) * kPi / 180;
  }
  return sigma;
}

// ---- exp_hyb ------------------------------------------------------------------------

template <typename T>
void BM_ExpHyb(benchmark::State& state) {
  const int order = static_cast<int>(state.range(0));
  const int spheres = static_cast<int>(state.range(1));
  const sh::Vec fd = log_vector(order, spheres);
  const std::vector<T> f(fd.begin(), fd.end());
  std::vector<T> out(f.size());
  const sh::HybOptions opt;
  sh::HybInfo info;
  sh::exp_hyb<T>(f, out, opt, &info);  // warm the per-order caches
  for (auto _ : state) {
    sh::exp_hyb<T>(f, out, opt, nullptr);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.counters["squarings"] = info.squarings;
  state.counters["norm"] = info.norm;
}
void ExpArgs(benchmark::internal::Benchmark* b) {
  b->ArgNames({"order", "spheres"});
  for (int spheres : {1, 10, 100})
    for (int order = 2; order <= sh::kMaxOrder; ++order) b->Args({order, spheres});
}
BENCHMARK(BM_ExpHyb<float>)->Apply(ExpArgs)->MinTime(0.2);
BENCHMARK(BM_ExpHyb<double>)->Apply(ExpArgs)->MinTime(0.2);

// ---- sphere accumulation --------------------------------------------------------------

void BM_AccumulateLogVisibility(benchmark::State& state) {
  const int order = static_cast<int>(state.range(0));
  const auto spheres = make_spheres(static_cast<int>(state.range(1)));
  const blockers::BlockerOptions opt;
  sh::Vec f(sh::num_coeffs(order));
  int kept = 0;
  for (auto _ : state) {
    std::fill(f.begin(), f.end(), 0.0);
    kept = blockers::accumulate_log_visibility(spheres, kOrigin, kUp, opt, f);
    benchmark::DoNotOptimize(f.data());
    benchmark::ClobberMemory();
  }
  state.counters["kept"] = kept;
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(spheres.size()));  // spheres/s
}
BENCHMARK(BM_AccumulateLogVisibility)
    ->ArgNames({"order", "spheres"})
    ->ArgsProduct({{4, 8}, {1, 10, 100}})
    ->MinTime(0.2);

// Log vector + exponentiation: the whole per-texel blocker cost at order 4 (float HYB).
void BM_BlockerVisibilityOrder4(benchmark::State& state) {
  constexpr int kOrder = 4;
  const auto spheres = make_spheres(static_cast<int>(state.range(0)));
  const blockers::BlockerOptions bopt;
  const sh::HybOptions hopt;
  sh::Vec f(sh::num_coeffs(kOrder));
  std::vector<float> ff(f.size()), out(f.size());
  for (auto _ : state) {
    std::fill(f.begin(), f.end(), 0.0);
    blockers::accumulate_log_visibility(spheres, kOrigin, kUp, bopt, f);
    for (std::size_t i = 0; i < f.size(); ++i) ff[i] = static_cast<float>(f[i]);
    sh::exp_hyb<float>(ff, out, hopt, nullptr);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_BlockerVisibilityOrder4)->ArgName("spheres")->Arg(1)->Arg(10)->Arg(100)->MinTime(0.2);

// ---- triple product -------------------------------------------------------------------

void BM_TripleProduct(benchmark::State& state) {
  const int order = static_cast<int>(state.range(0));
  const auto& tp = sh::triple_product(order);
  const sh::Vec f = random_vector(order, 1), g = random_vector(order, 2);
  sh::Vec out(f.size());
  for (auto _ : state) {
    tp.product(f, g, out);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.counters["nonzeros"] = static_cast<double>(tp.entries().size());
}
BENCHMARK(BM_TripleProduct)->ArgName("order")->DenseRange(2, sh::kMaxOrder)->MinTime(0.2);

template <typename T>
void BM_TruncatedProduct(benchmark::State& state) {
  const int order = static_cast<int>(state.range(0));
  const sh::Vec fd = random_vector(order, 1), gd = random_vector(order, 2);
  const std::vector<T> f(fd.begin(), fd.end()), g(gd.begin(), gd.end());
  std::vector<T> out(f.size());
  sh::truncated_product<T>(f, g, out);
  for (auto _ : state) {
    sh::truncated_product<T>(f, g, out);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_TruncatedProduct<float>)->ArgName("order")->DenseRange(2, sh::kMaxOrder)->MinTime(0.2);
BENCHMARK(BM_TruncatedProduct<double>)->ArgName("order")->DenseRange(2, sh::kMaxOrder)->MinTime(0.2);

// ---- wedge operators ------------------------------------------------------------------

constexpr int kWedgeShOrder = 4;

sh::WedgeInterpolation interp_of(std::int64_t v) {
  return v == 0 ? sh::WedgeInterpolation::Linear : sh::WedgeInterpolation::BSpline;
}

void WedgeArgs(benchmark::internal::Benchmark* b) {
  b->ArgNames({"W", "N", "bspline"});
  b->ArgsProduct({{16, 32, 64}, {4, 8}, {0, 1}});
}

void BM_WedgeAssemble(benchmark::State& state) {
  const int w = static_cast<int>(state.range(0)), n = static_cast<int>(state.range(1));
  const auto& op = sh::wedge_operator(kWedgeShOrder, n, w, interp_of(state.range(2)));
  const auto sigma = make_horizon(w);
  std::vector<double> slices(static_cast<std::size_t>(w) * n);
  for (int j = 0; j < w; ++j) sh::nlp_visibility(sigma[j], std::span(slices).subspan(std::size_t(j) * n, n));
  sh::Vec out(sh::num_coeffs(kWedgeShOrder));
  for (auto _ : state) {
    op.assemble(slices, out);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_WedgeAssemble)->Apply(WedgeArgs)->MinTime(0.1);

// Slices from the horizon + assembly: the per-texel cost of `shaded` after the march.
void BM_VisibilityFromHorizon(benchmark::State& state) {
  const int w = static_cast<int>(state.range(0)), n = static_cast<int>(state.range(1));
  const auto& op = sh::wedge_operator(kWedgeShOrder, n, w, interp_of(state.range(2)));
  const auto sigma = make_horizon(w);
  std::vector<double> scratch(static_cast<std::size_t>(w) * n);
  sh::Vec out(sh::num_coeffs(kWedgeShOrder));
  for (auto _ : state) {
    sh::visibility_from_horizon(op, sigma, scratch, out);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_VisibilityFromHorizon)->Apply(WedgeArgs)->MinTime(0.1);

// One-off construction of an operator (exact quadrature; cached by wedge_operator()).
void BM_WedgeOperatorBuild(benchmark::State& state) {
  const int w = static_cast<int>(state.range(0)), n = static_cast<int>(state.range(1));
  for (auto _ : state) {
    sh::WedgeOperator op(kWedgeShOrder, n, w, interp_of(state.range(2)));
    benchmark::DoNotOptimize(op.matrix().data());
  }
  state.SetLabel("one-off, cached");
}
BENCHMARK(BM_WedgeOperatorBuild)
    ->ArgNames({"W", "N", "bspline"})
    ->Args({32, 8, 0})
    ->Args({32, 8, 1})
    ->Unit(benchmark::kMicrosecond)
    ->MinTime(0.1);

// ---- NLP slices -----------------------------------------------------------------------

void BM_NlpVisibility(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  std::vector<double> out(n);
  double sigma = 0.3;
  for (auto _ : state) {
    benchmark::DoNotOptimize(sigma);
    sh::nlp_visibility(sigma, out);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_NlpVisibility)->ArgName("N")->Arg(4)->Arg(8)->Arg(16)->MinTime(0.1);

void BM_NlpLogVisibility(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  std::vector<double> out(n);
  double sigma = 0.3;
  const double log_eps = std::log(sh::kDefaultLogEpsilon);
  for (auto _ : state) {
    benchmark::DoNotOptimize(sigma);
    sh::nlp_log_visibility(sigma, log_eps, out);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_NlpLogVisibility)->ArgName("N")->Arg(4)->Arg(8)->Arg(16)->MinTime(0.1);

// ---- SH rotation ----------------------------------------------------------------------

glm::dmat3 test_rotation() {
  // Rotation about a skew unit axis by 0.7 rad (Rodrigues), columns = images of x, y, z.
  const glm::dvec3 k = glm::normalize(glm::dvec3(0.3, -0.5, 0.8));
  const double c = std::cos(0.7), s = std::sin(0.7);
  glm::dmat3 r;
  for (int col = 0; col < 3; ++col) {
    glm::dvec3 e(0.0);
    e[col] = 1.0;
    r[col] = e * c + glm::cross(k, e) * s + k * glm::dot(k, e) * (1 - c);
  }
  return r;
}

void BM_RotateZ(benchmark::State& state) {
  const int order = static_cast<int>(state.range(0));
  sh::Vec v = random_vector(order, 3);
  double alpha = 0.37;
  for (auto _ : state) {
    benchmark::DoNotOptimize(alpha);
    sh::rotate_z_inplace(v, alpha);
    benchmark::DoNotOptimize(v.data());
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_RotateZ)->ArgName("order")->Arg(4)->Arg(8)->MinTime(0.1);

void BM_AddRotatedZh(benchmark::State& state) {
  const int order = static_cast<int>(state.range(0));
  const sh::Vec zh = sh::cap_zh(order, 0.9);
  const glm::dvec3 axis = glm::normalize(glm::dvec3(0.2, 0.4, 0.9));
  sh::Vec out(sh::num_coeffs(order), 0.0);
  for (auto _ : state) {
    sh::add_rotated_zh(zh, axis, 1e-3, out);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_AddRotatedZh)->ArgName("order")->Arg(4)->Arg(8)->MinTime(0.1);

void BM_ShRotationBuild(benchmark::State& state) {
  const int order = static_cast<int>(state.range(0));
  const glm::dmat3 r = test_rotation();
  for (auto _ : state) {
    sh::ShRotation rot(order, r);
    benchmark::DoNotOptimize(rot.band(order - 1).data());
  }
}
BENCHMARK(BM_ShRotationBuild)->ArgName("order")->Arg(4)->Arg(8)->Unit(benchmark::kMicrosecond)->MinTime(0.1);

void BM_ShRotationApply(benchmark::State& state) {
  const int order = static_cast<int>(state.range(0));
  const sh::ShRotation rot(order, test_rotation());
  const sh::Vec in = random_vector(order, 4);
  sh::Vec out(in.size());
  for (auto _ : state) {
    rot.apply(in, out);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_ShRotationApply)->ArgName("order")->Arg(4)->Arg(8)->MinTime(0.1);

}  // namespace
