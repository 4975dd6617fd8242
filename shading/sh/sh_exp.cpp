#include "shading/sh/sh_exp.h"

#include "shading/sh/hyb_table.h"
#include "shading/sh/sh_product.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <stdexcept>

namespace skylit::sh {
namespace {

template <typename T>
struct Entry {
  std::uint8_t i, j, k;
  T value;
};

// Γ in T, built once per order (call_once: a lock-free check after the first call).
template <typename T>
const std::vector<Entry<T>>& product_entries(int order) {
  static std::array<std::once_flag, kMaxOrder + 1> once;
  static std::array<std::vector<Entry<T>>, kMaxOrder + 1> cache;
  if (order < kMinOrder || order > kMaxOrder) throw std::invalid_argument("truncated_product: order out of range");
  std::call_once(once[order], [order] {
    for (const auto& e : triple_product(order).entries())
      cache[order].push_back({static_cast<std::uint8_t>(e.i), static_cast<std::uint8_t>(e.j),
                              static_cast<std::uint8_t>(e.k), static_cast<T>(e.value)});
  });
  return cache[order];
}

}  // namespace

template <typename T>
void truncated_product(std::span<const T> f, std::span<const T> g, std::span<T> out) {
  const int order = order_of(f.size());
  if (g.size() != f.size() || out.size() != f.size()) throw std::invalid_argument("truncated_product: size mismatch");
  std::array<T, kMaxOrder * kMaxOrder> acc{};  // out may alias f or g
  for (const auto& e : product_entries<T>(order)) acc[e.i] += e.value * f[e.j] * g[e.k];
  std::copy_n(acc.begin(), f.size(), out.begin());
}

template <typename T>
void exp_hyb(std::span<const T> f, std::span<T> out, const HybOptions& opt, HybInfo* info) {
  const int order = order_of(f.size());
  const std::size_t nc = f.size();
  if (order > kMaxOrder || out.size() != nc) throw std::invalid_argument("exp_hyb: bad sizes");
  HybInfo local;
  HybInfo& inf = info ? *info : local;
  inf = {};
  const T s4pi = static_cast<T>(kSqrt4Pi);
  std::array<T, kMaxOrder * kMaxOrder> h{}, g{}, sq{};
  const std::span<T> hs(h.data(), nc), gs(g.data(), nc), sqs(sq.data(), nc);

  // 1. DC isolation; optional floor on the mean log (shape kept by scaling all of f).
  T f0 = f[0];
  T shape = 1;
  if (opt.log_floor_epsilon > 0.0) {
    const T floor = s4pi * static_cast<T>(std::log(opt.log_floor_epsilon));
    if (f0 < floor) {
      shape = floor / f0;
      f0 = floor;
      inf.floor_clamped = true;
    }
  }
  const T c = f0 / s4pi;
  T amax = 0;
  for (std::size_t i = 1; i < nc; ++i) amax = std::max(amax, std::abs(f[i]));
  T unit_norm = 0;  // ‖f̂/amax‖ ∈ [1, n]: no overflow in float
  if (amax > 0) {
    for (std::size_t i = 1; i < nc; ++i) unit_norm += (f[i] / amax) * (f[i] / amax);
    unit_norm = std::sqrt(unit_norm);
  }
  const double m = static_cast<double>(shape) * static_cast<double>(amax) * static_cast<double>(unit_norm);
  inf.norm = m;

  // 2. k = smallest with m/2^k ≤ t, capped; beyond the cap ‖h‖ is clamped to t.
  const int kmax = std::clamp(opt.max_squarings, 0, kHybSquaringsCap);
  int k = 0;
  double mh = m;
  while (mh > opt.threshold && k < kmax) {
    mh *= 0.5;
    ++k;
  }
  if (mh > opt.threshold) {
    mh = opt.threshold;
    inf.norm_clamped = true;
  }
  inf.squarings = k;
  h[0] = 0;
  if (amax > 0) {
    const T to_h = static_cast<T>(mh) / unit_norm;  // h = (f̂/amax)·(‖h‖/‖f̂/amax‖)
    for (std::size_t i = 1; i < nc; ++i) h[i] = (f[i] / amax) * to_h;
  }

  // 3. Base g ≈ exp*(h); its DC is > 0 for every base (a ≥ 1 by Jensen, (h*h)_0 ≥ 0).
  switch (opt.base) {
    case HybBase::kOptimalLinear: {
      const auto [a, b] = hyb_table(order).lookup(mh);
      for (std::size_t i = 0; i < nc; ++i) g[i] = static_cast<T>(b) * h[i];
      g[0] += static_cast<T>(a) * s4pi;
      break;
    }
    case HybBase::kTaylor2:
      truncated_product<T>(hs, hs, sqs);
      for (std::size_t i = 0; i < nc; ++i) g[i] = h[i] + T(0.5) * sq[i];
      g[0] += s4pi;
      break;
    case HybBase::kTaylor1:
      for (std::size_t i = 0; i < nc; ++i) g[i] = h[i];
      g[0] += s4pi;
      break;
  }

  // 4. k squarings. Renormalised: g_true = e^{log_scale}·g with g_0 = √(4π); each
  // squaring's DC is ‖g‖²/(4π) ≥ 1, so the log is finite and ≥ 0.
  T log_scale = 0;
  const auto renormalise = [&] {
    const T d = g[0] / s4pi;
    for (std::size_t i = 0; i < nc; ++i) g[i] /= d;
    g[0] = s4pi;
    return std::log(d);
  };
  if (opt.renormalise) log_scale = renormalise();
  for (int s = 0; s < k; ++s) {
    truncated_product<T>(gs, gs, gs);
    if (opt.renormalise) log_scale = 2 * log_scale + renormalise();
  }

  // 5. Apply e^c (and the log scale) once, with the output guards.
  if (opt.renormalise) {
    T lsum = c + log_scale;
    if (opt.clamp_output_dc && lsum > 0) {  // DC value e^{lsum} ≤ 1
      lsum = 0;
      inf.dc_clamped = true;
    }
    T gmax = 0;
    for (std::size_t i = 0; i < nc; ++i) gmax = std::max(gmax, std::abs(g[i]));
    const T lmax = std::log(std::numeric_limits<T>::max()) - std::log(gmax) - static_cast<T>(kHybOverflowMargin);
    lsum = std::min(lsum, lmax);
    if (lsum < std::log(std::numeric_limits<T>::min()) + static_cast<T>(kHybFlushMargin)) {
      std::fill(out.begin(), out.end(), T(0));
      inf.flushed = true;
      return;
    }
    const T e = std::exp(lsum);
    for (std::size_t i = 0; i < nc; ++i) out[i] = e * g[i];
    return;
  }
  const T e = std::exp(c);  // plain HYB: 0·inf = NaN in float once c ≲ −103
  for (std::size_t i = 0; i < nc; ++i) out[i] = e * g[i];
  if (opt.clamp_output_dc && out[0] > s4pi) {
    const T r = s4pi / out[0];
    for (std::size_t i = 0; i < nc; ++i) out[i] *= r;
    inf.dc_clamped = true;
  }
}

Vec exp_hyb(std::span<const double> f, const HybOptions& opt, HybInfo* info) {
  Vec out(f.size());
  exp_hyb<double>(f, out, opt, info);
  return out;
}

template void exp_hyb<float>(std::span<const float>, std::span<float>, const HybOptions&, HybInfo*);
template void exp_hyb<double>(std::span<const double>, std::span<double>, const HybOptions&, HybInfo*);
template void truncated_product<float>(std::span<const float>, std::span<const float>, std::span<float>);
template void truncated_product<double>(std::span<const double>, std::span<const double>, std::span<double>);

}  // namespace skylit::sh
