// SH rotations: about z by an angle (cheap, per band), a zonal (ZH) vector
// rotated toward a direction (addition theorem), and general 3D rotations.
#pragma once

#include "shading/sh/sh_basis.h"

#include <glm/mat3x3.hpp>

#include <array>

namespace skylit::sh {

// Rotates the *function* by +alpha about z: f_new(φ) = f_old(φ − alpha).
void rotate_z_inplace(std::span<double> coeffs, double alpha);
Vec rotate_z(std::span<const double> coeffs, double alpha);

// √(4π/(2l+1)): the factor of z_l·y_lm(axis) in a rotated ZH (below; the GPU's
// tables are scaled by it).
double zh_rotation_factor(int l);

// ZH vector z_l (l < order) rotated so that its axis points along `axis`
// (unit): f_lm = zh_rotation_factor(l)·z_l·y_lm(axis).
Vec rotate_zh(std::span<const double> zh, const glm::dvec3& axis);
// The same, accumulated into `out` (order = sqrt(out.size())) with a scale.
void add_rotated_zh(std::span<const double> zh, const glm::dvec3& axis, double scale, std::span<double> out);

// General 3D rotation R (orthonormal, det +1; checked to 1e-6) of SH functions.
// The function is carried along by R: f_new(R·ω) = f(ω), so R = Rz(α) gives
// rotate_z(α) and a rotation taking +z to `axis` turns a ZH into rotate_zh.
// Block-diagonal per band: D^l[m][m'] = ∫ y_lm(ω) y_lm'(Rᵀω) dω, projected by
// the product rule (GL in z × midpoint in φ, n × (2n−1) nodes), which is exact
// for the band-limited integrand of degree ≤ 2(n−1): error ≈ 1e-15.
// Offset of band l's block in a concatenation of (2k+1)² blocks, k < l.
constexpr std::size_t rotation_band_offset(int l) { return static_cast<std::size_t>(l * (4 * l * l - 1) / 3); }

class ShRotation {
 public:
  ShRotation(int order, const glm::dmat3& rotation);
  int order() const { return order_; }
  // Band l's block, row-major (2l+1)×(2l+1), rows and columns indexed by m + l.
  std::span<const double> band(int l) const;
  // out = D·in; in and out have n² entries and may be the same span. No allocation.
  void apply(std::span<const double> in, std::span<double> out) const;
  Vec apply(std::span<const double> in) const;

 private:
  int order_;
  std::array<double, rotation_band_offset(kMaxOrder)> blocks_{};  // Σ_l (2l+1)² = 680 at order 8
};

// One-off rotation of an SH vector (builds the ShRotation).
Vec rotate(std::span<const double> coeffs, const glm::dmat3& rotation);

}  // namespace skylit::sh
