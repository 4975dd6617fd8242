// Optimal-linear (OL) table of HYB exponentiation (Ren et al. 2006 as
// reconstructed in math-notes §6.2): exp*(h) ≈ a(m)·1 + b(m)·h, m = ‖h‖, for a
// DC-free log vector h. a, b come from least squares on the family of single
// spherical blockers, log ε·cap(α) with its DC removed, against the pointwise
// band-limited exp* (T1); they are computed here at start-up, never typed.
#pragma once

#include <utility>
#include <vector>

namespace skylit::sh {

struct HybTable {
  int order = 0;
  double epsilon = 0.0;  // training family log ε·cap(α)
  double m_step = 0.0;   // a, b sampled at m = j·m_step, j = 0 … size−1
  std::vector<double> a, b;

  double m_max() const { return m_step * static_cast<double>(a.size() - 1); }
  // (a, b) at m, linearly interpolated; m is clamped to [0, m_max()].
  std::pair<double, double> lookup(double m) const;
};

// Because 1 ⊥ h, the least-squares fit of ĝ = T1(h) by a·1 + b·h is exactly
// a = ĝ_0/√(4π), b = ⟨ĝ, h⟩/‖h‖², with m → 0 limits a = b = 1. Only the
// increasing branch of m(α), α ∈ (0, π/2], is used; m_max is cut to its peak.
HybTable build_hyb_table(int order, double epsilon, double m_max, int samples);

// Default table per order (built once, thread-safe): ε = 0.1, m ∈ [0, 2], 129 samples.
// The fit depends on ε by < 1e-3 for m ≤ 0.5 (math-notes T6), so one table serves all ε.
const HybTable& hyb_table(int order);

inline constexpr double kHybTableEpsilon = 0.1;
inline constexpr double kHybTableMaxNorm = 2.0;
inline constexpr int kHybTableSamples = 129;

}  // namespace skylit::sh
