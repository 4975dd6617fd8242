// SH rotations: about z by an angle (cheap, per band), a zonal (ZH) vector
// rotated toward a direction (addition theorem), and general 3D rotations.
#pragma once

#include "shading/sh_basis.h"

namespace skylit::sh {

// Rotates the *function* by +alpha about z: f_new(φ) = f_old(φ − alpha).
void rotate_z_inplace(std::span<double> coeffs, double alpha);
Vec rotate_z(std::span<const double> coeffs, double alpha);

// ZH vector z_l (l < order) rotated so that its axis points along `axis`
// (unit): f_lm = √(4π/(2l+1))·z_l·y_lm(axis).
Vec rotate_zh(std::span<const double> zh, const glm::dvec3& axis);
// The same, accumulated into `out` (order = sqrt(out.size())) with a scale.
void add_rotated_zh(std::span<const double> zh, const glm::dvec3& axis, double scale, std::span<double> out);

}  // namespace skylit::sh
