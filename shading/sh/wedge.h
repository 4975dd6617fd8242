// Wedge operators: NLP slice vectors at W azimuths → one SH vector
// (NS09 §5 and Appendix A; math-notes §3, with the corrections of §10.15–17).
//
// Samples sit at φ_j = j·2π/W in the math frame (from +x toward +y). Wedge j
// spans [φ_j, φ_j + Δφ]; inside it the slice function is interpolated in
// α = (φ − φ_j)/Δφ from neighbouring samples and expanded in the NLP basis:
//   linear   : samples j, j+1         weights (1−α, α)
//   B-spline : samples j−1 … j+2      uniform cubic weights (approximating)
// The operator M (n² × taps·N) is the SH projection of that canonical wedge
// [0, Δφ]; M[(l,m), s·N + l'] = A_{m,s} · B_{l,|m|,l'} with A the azimuthal
// and B the polar moments. Assembly sums all W wedges, wrap-around included:
//   V = Σ_{j=0}^{W−1} Rz(φ_j) · M · [v_{j+first_tap} ; … ]   (indices mod W).
#pragma once

#include "shading/sh/sh_basis.h"

#include <span>
#include <vector>

namespace skylit::sh {

enum class WedgeInterpolation { Linear, BSpline };

inline constexpr int kMaxNlpOrder = 64;

// Taps per wedge: 2 (linear) or 4 (B-spline).
int interpolation_taps(WedgeInterpolation interp);
// Index of the first tap relative to the wedge's own sample j: 0 or −1.
int interpolation_first_tap(WedgeInterpolation interp);
// Weights of the taps at α ∈ [0, 1]; weights.size() ≥ taps.
void interpolation_weights(WedgeInterpolation interp, double alpha, std::span<double> weights);

class WedgeOperator {
 public:
  // sh_order n in [1, kMaxOrder], nlp_order N in [n, kMaxNlpOrder], azimuths W ≥ 1.
  // Throws std::invalid_argument otherwise. Builds M by exact quadrature.
  WedgeOperator(int sh_order, int nlp_order, int azimuths, WedgeInterpolation interp);

  int sh_order() const { return sh_order_; }
  int nlp_order() const { return nlp_order_; }
  int azimuths() const { return azimuths_; }
  WedgeInterpolation interpolation() const { return interp_; }
  int taps() const { return interpolation_taps(interp_); }
  int first_tap() const { return interpolation_first_tap(interp_); }
  int rows() const { return num_coeffs(sh_order_); }
  int cols() const { return taps() * nlp_order_; }
  double wedge_angle() const;          // Δφ = 2π/W
  double sample_azimuth(int j) const;  // φ_j = j·Δφ

  // M, row-major rows() × cols(); column s·N + l' multiplies v_{j+first_tap+s}[l'].
  std::span<const double> matrix() const { return matrix_; }
  // The same values rounded to float, for upload to the GPU.
  std::span<const float> matrix_f32() const { return matrix_f32_; }

  // slices: W NLP vectors of length N, contiguous (sample j at j·N).
  // out: n² coefficients, overwritten. No allocation.
  void assemble(std::span<const double> slices, std::span<double> out) const;
  Vec assemble(std::span<const double> slices) const;

 private:
  int sh_order_, nlp_order_, azimuths_;
  WedgeInterpolation interp_;
  std::vector<double> matrix_;
  std::vector<float> matrix_f32_;
  std::vector<double> columns_;                // M transposed: column c at [c·n²], for a vectorisable assemble
  std::vector<double> cos_m_phi_, sin_m_phi_;  // [j·n + m]: cos(m φ_j), sin(m φ_j)
};

// Cached operator, built once per parameter set (thread-safe; the reference
// stays valid for the life of the program).
const WedgeOperator& wedge_operator(int sh_order, int nlp_order, int azimuths, WedgeInterpolation interp);

// SH visibility from horizon elevations sigma[j] at φ_j (radians, j < W).
// scratch.size() ≥ W·N holds the slices; out.size() = n². No allocation.
void visibility_from_horizon(const WedgeOperator& op, std::span<const double> sigma, std::span<double> scratch,
                             std::span<double> out);
Vec visibility_from_horizon(const WedgeOperator& op, std::span<const double> sigma);

// SH log-visibility log ε · occlusion from the same horizon (log_eps < 0).
void log_visibility_from_horizon(const WedgeOperator& op, std::span<const double> sigma, double log_eps,
                                 std::span<double> scratch, std::span<double> out);
Vec log_visibility_from_horizon(const WedgeOperator& op, std::span<const double> sigma, double log_eps);

}  // namespace skylit::sh
