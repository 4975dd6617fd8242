// The log-visibility ZH of a sphere's cap as the inverse of the exponential HYB
// approximates (Ren et al. 2006): log*(V_cap) = log(M_V)·1 in the truncated product
// algebra (sh_exp_reference.h), tabulated over s² = (r/d)². The plain log ε·cap of
// LSH eq. 26 is what a pointwise exp would invert, but a small cap's band-limited
// vector is so spread out that exp* acts on it as 1 + f: the sphere then hides
// |log ε|/(1 − ε) = 2.6× its own sky at ε = 0.1. With log*, exp*(log*(V)) = V, so a
// lone sphere hides what its SH visibility does, at any size.
#pragma once

#include <span>
#include <vector>

namespace skylit::blockers {

class CapLogTable {
 public:
  // Entries over s² ∈ [0, 1]; log* eigenvalues are clipped at epsilon.
  CapLogTable(int order, double epsilon, int entries = kEntries);
  int order() const { return order_; }
  // The ZH (n coefficients) of log*(V) for a cap of a sphere with r/d = s ∈ [0, 1],
  // linear in s² between entries (exact as s → 0, where the log is ∝ s²).
  void log_zh(double s, std::span<double> out) const;
  // Entries × order doubles, row per entry (the GPU's copy). Row 0 (s = 0) is zero.
  std::span<const double> values() const { return values_; }
  // log_zh(s)[l] / s² below the first entry (s² < 1/(entries − 1)), where the table is
  // one linear piece from zero: nearly every cap of an aircraft seen from the ground
  // (d > 32 r), so the GPU takes these n numbers instead of reading two rows.
  double first_slope(int l) const { return values_[static_cast<std::size_t>(order_) + l] * (entries_ - 1); }
  int entries() const { return entries_; }

  static constexpr int kEntries = 1024;

 private:
  int order_, entries_;
  std::vector<double> values_;
};

// The table for (order, ε), built once per pair and kept (thread-safe).
const CapLogTable& cap_log_table(int order, double epsilon);

}  // namespace skylit::blockers
