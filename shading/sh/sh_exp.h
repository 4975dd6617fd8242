// SH exponentiation of a log-SH vector f (math-notes §6, §9):
//  * T1 exp_pointwise: P_n[exp(Σ f_i y_i)] by quadrature (the band-limited exp*);
//  * T2 exp_product_algebra: expm(M_f)·1, the exponential in the truncated-product
//    algebra, which HYB approximates (the product is not associative, §5);
//  * HYB exp_hyb: DC isolation, a base for a scaled-down h = f̂/2^k, k squarings
//    with the truncated product, plus the guards of §9 (templated on float/double).
// DC isolation is exact for all three: exp*(f) = e^{f_0/√(4π)}·exp*(f − f_0 e_0).
// T1 and T2 are in sh_exp_reference.h (included here), which the HYB table
// (hyb_table.h) is fitted against: sh_exp -> hyb_table -> sh_exp_reference.
#pragma once

#include "shading/sh/sh_basis.h"
#include "shading/sh/sh_exp_reference.h"

#include <span>

namespace skylit::sh {

// Default ε of log-visibility (log ε inside a blocker) and of the HYB log floor:
// the best or near-best vector error over 10–400 overlapping spheres with the
// guards on, shadows still 90 % opaque (docs/numerics.md §2, table D).
inline constexpr double kDefaultLogEpsilon = 0.1;

enum class HybBase {
  kOptimalLinear,  // g = a(m)·1 + b(m)·h, table from single caps (hyb_table.h)
  kTaylor2,        // PS2: g = 1 + h + h*h/2 (one extra product)
  kTaylor1,        // g = 1 + h
};

// Defaults chosen from the measurements in docs/numerics.md §2.
struct HybOptions {
  // PS2 beats OL 2–22× on single spheres and ~30× on height-field vectors, ties
  // on heavy overlap, for one extra product.
  HybBase base = HybBase::kTaylor2;
  double threshold = 0.25;  // k = smallest with ‖f̂‖/2^k ≤ threshold (PS2 base error ∝ t³)
  // Cap on k (cost bound): ‖f̂‖ ≤ 1024 exact at t = 0.25. Beyond it, f̂ is scaled
  // down to ‖f̂‖ = threshold·2^max_squarings.
  int max_squarings = 12;
  // Divide g by its DC after the base and each squaring, accumulate the log of
  // the scale, apply e^{c + log scale} once; flush to 0 below ln(T_min) + 8
  // (≈ −79 in float). Off = plain HYB (float32 NaN once c ≲ −103).
  bool renormalise = true;
  // > 0: clamp f_0 ≥ √(4π)·ln(log_floor_epsilon) by scaling the whole f (shape
  // kept): the mean log-visibility may not go below ln ε. Set it to the ε the log
  // vector was built with; 0 disables. Fires only under heavy overlap (mean
  // occlusion count > 1), where it cuts the error 3–140× at ε ≤ 0.2 (table D).
  double log_floor_epsilon = kDefaultLogEpsilon;
  // Rescale the result so its DC coefficient is ≤ √(4π) (visibility ≤ 1 on average).
  bool clamp_output_dc = true;
};

// Output guards of renormalised HYB (natural-log margins): the exponent of the scale
// stays kHybOverflowMargin below overflow of the largest coefficient, and results
// whose scale is below ln(T_min) + kHybFlushMargin are flushed to 0.
inline constexpr double kHybOverflowMargin = 1.0;
inline constexpr double kHybFlushMargin = 8.0;
// HybOptions::max_squarings is clamped to [0, kHybSquaringsCap].
inline constexpr int kHybSquaringsCap = 30;

struct HybInfo {
  int squarings = 0;
  double norm = 0.0;           // ‖f̂‖ after the log-floor clamp
  bool floor_clamped = false;  // log-floor guard fired
  bool norm_clamped = false;   // ‖f̂‖ > threshold·2^max_squarings was scaled down
  bool dc_clamped = false;     // output DC guard fired
  bool flushed = false;        // result flushed to 0
};

// out = HYB exp*(f); f and out have n² entries, n ≤ kMaxOrder. No allocation
// after the first call per order (product and OL tables are cached).
template <typename T>
void exp_hyb(std::span<const T> f, std::span<T> out, const HybOptions& opt = {}, HybInfo* info = nullptr);
Vec exp_hyb(std::span<const double> f, const HybOptions& opt = {}, HybInfo* info = nullptr);

// Truncated SH product in T (Γ from triple_product(order), cached per order).
template <typename T>
void truncated_product(std::span<const T> f, std::span<const T> g, std::span<T> out);

extern template void exp_hyb<float>(std::span<const float>, std::span<float>, const HybOptions&, HybInfo*);
extern template void exp_hyb<double>(std::span<const double>, std::span<double>, const HybOptions&, HybInfo*);
extern template void truncated_product<float>(std::span<const float>, std::span<const float>, std::span<float>);
extern template void truncated_product<double>(std::span<const double>, std::span<const double>, std::span<double>);

}  // namespace skylit::sh
