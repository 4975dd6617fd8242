// Closed-form zonal harmonics (ZH) of two profiles that several libraries need: the
// indicator of a spherical cap (sphere blockers, the HYB table's training family) and
// the clamped cosine power max(t, 0)^r (irradiance from SH, BRDF lobes).
//
// A ZH vector z_l (l < order) holds the m = 0 coefficients of a profile g(t), t = cos θ,
// about +z: z_l = √(π(2l+1))·∫_{−1}^{1} g(t) P_l(t) dt. Rotate it with rotate_zh /
// add_rotated_zh (sh_rotation.h).
#pragma once

#include "shading/sh/sh_basis.h"

#include <span>

namespace skylit::sh {

// Solid angle 2π(1 − cos α) of a cap.
double cap_solid_angle(double cos_alpha);

// ZH (z_0 … z_{n−1}, n = out.size() ≤ kMaxOrder) of the cap indicator {θ ≤ α}:
// z_0 = √π(1−c), z_l = √(π(2l+1))·(P_{l−1}(c) − P_{l+1}(c))/(2l+1), c = cos α.
void cap_zh(double cos_alpha, std::span<double> out);
Vec cap_zh(int order, double cos_alpha);
// Visibility ZH of the same cap: (√(4π) − z_0, −z_1, …).
Vec cap_visibility_zh(int order, double cos_alpha);
// Log-visibility ZH: log ε·z (times `attenuation`, 1 unless ratio attenuation).
Vec cap_log_visibility_zh(int order, double cos_alpha, double epsilon, double attenuation = 1.0);

// ZH of scale·max(t, 0)^r for real r > −1, through J_l = ∫_0^1 t^r P_l(t) dt:
// J_0 = 1/(r+1), J_1 = 1/(r+2), J_l = (r−l+2)/(r+l+1)·J_{l−2}; z_l = √(π(2l+1))·scale·J_l.
// Throws std::invalid_argument for an order out of range or r ≤ −1.
Vec clamped_cosine_power_zh(int order, double r, double scale = 1.0);
// ZH of max(cos θ, 0): (√π/2, √(π/3), √(5π)/8, 0, …).
Vec clamped_cosine_zh(int order);

}  // namespace skylit::sh
