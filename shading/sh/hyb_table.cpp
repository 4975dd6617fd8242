#include "shading/sh/hyb_table.h"

#include "shading/sh/sh_basis.h"
#include "shading/sh/sh_exp_reference.h"
#include "shading/sh/zonal.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <stdexcept>

namespace skylit::sh {
namespace {

// DC-free log ZH of the cap of half-angle α, and its norm m.
Vec family_member(int order, double epsilon, double alpha) {
  Vec h = cap_log_visibility_zh(order, std::cos(alpha), epsilon);
  h[0] = 0.0;
  return h;
}

double norm(const Vec& v) { return std::sqrt(dot(v, v)); }

}  // namespace

std::pair<double, double> HybTable::lookup(double m) const {
  if (a.size() < 2 || !(m > 0.0)) return {a.front(), b.front()};
  const double x = std::min(m / m_step, static_cast<double>(a.size() - 1));
  const std::size_t j = std::min(static_cast<std::size_t>(x), a.size() - 2);
  const double t = x - static_cast<double>(j);
  return {a[j] + t * (a[j + 1] - a[j]), b[j] + t * (b[j + 1] - b[j])};
}

HybTable build_hyb_table(int order, double epsilon, double m_max, int samples) {
  if (order < kMinOrder || order > kMaxOrder) throw std::invalid_argument("build_hyb_table: order out of range");
  if (samples < 2 || !(m_max > 0.0)) throw std::invalid_argument("build_hyb_table: need ≥ 2 samples and m_max > 0");
  // Peak of m(α) on α ∈ (0, π/2]: the end of the increasing branch.
  constexpr int kScan = 2048;
  double alpha_peak = 0.0, m_peak = 0.0;
  for (int i = 1; i <= kScan; ++i) {
    const double alpha = 0.5 * kPi * i / kScan;
    const double m = norm(family_member(order, epsilon, alpha));
    if (m <= m_peak) break;
    m_peak = m;
    alpha_peak = alpha;
  }
  HybTable t;
  t.order = order;
  t.epsilon = epsilon;
  if (m_peak <= 0.0) {  // order 1: no DC-free part; exp*(0) = 1
    t.m_step = m_max;
    t.a = {1.0, 1.0};
    t.b = {1.0, 1.0};
    return t;
  }
  const double top = std::min(m_max, m_peak);
  t.m_step = top / (samples - 1);
  t.a.assign(samples, 1.0);  // m → 0: a → 1, b → 1 (first-order Taylor)
  t.b.assign(samples, 1.0);
  for (int j = 1; j < samples; ++j) {
    const double target = j * t.m_step;
    double lo = 0.0, hi = alpha_peak;  // bisection for m(α) = target on the increasing branch
    for (int it = 0; it < 80; ++it) {
      const double mid = 0.5 * (lo + hi);
      (norm(family_member(order, epsilon, mid)) < target ? lo : hi) = mid;
    }
    const Vec h = family_member(order, epsilon, 0.5 * (lo + hi));
    const Vec g = exp_pointwise_zh(h);
    const double m2 = dot(h, h);
    t.a[j] = g[0] / kSqrt4Pi;
    t.b[j] = dot(g, h) / m2;
  }
  return t;
}

const HybTable& hyb_table(int order) {
  static std::array<std::once_flag, kMaxOrder + 1> once;
  static std::array<HybTable, kMaxOrder + 1> cache;
  if (order < kMinOrder || order > kMaxOrder) throw std::invalid_argument("hyb_table: order out of range");
  std::call_once(once[order], [order] {
    cache[order] = build_hyb_table(order, kHybTableEpsilon, kHybTableMaxNorm, kHybTableSamples);
  });
  return cache[order];
}

}  // namespace skylit::sh
