// Reflectance lobes as zonal harmonics (ZH), plain and logarithmic
// (math-notes §7; LSH §5 eq. 27).
//
// Every lobe here is zonal about an axis a and has the profile
//   g_r(t) = (r+1)/(2π)·max(t, 0)^r,   t = ω·a,
// normalised so that ∫ g_r dω = 1 over the hemisphere about a.
//   * Lambert (albedo 1): the BRDF 1/π times the cosine, g_1(n·ω) = max(n·ω, 0)/π,
//     axis = the normal n.
//   * Phong of exponent r: g_r(R·ω) about the reflected view direction R. The
//     cosine n·ω is folded into the lobe (the seed's and Ramamoorthi–Hanrahan's
//     reflected parametrisation); the normal's hemisphere is imposed only by the
//     visibility, whose floor is the tangent plane (DESIGN step 3).
// So outgoing radiance is ∫ L(ω)·V(ω)·g_r(ω·a) dω for both kinds, and Lambert is
// exactly Phong with r = 1.
//
// A ZH vector z_l (l < order) holds the m = 0 coefficients of the lobe about +z:
//   z_l = 2π ∫_{−1}^{1} g(t)·y_l0(t) dt = √(π(2l+1))·∫_{−1}^{1} g(t) P_l(t) dt.
// It is rotated toward a with sh::rotate_zh / sh::add_rotated_zh. The lobe without its
// normalisation, max(cos θ, 0)^r, is sh::clamped_cosine_power_zh (shading/sh/zonal.h).
#pragma once

#include "shading/sh/sh_basis.h"

namespace skylit::shading {

enum class BrdfKind { Lambert, Phong };

struct Brdf {
  BrdfKind kind = BrdfKind::Lambert;
  double phong_exponent = 16.0;  // r, used only by Phong; r > 0

  // The lobe exponent: 1 for Lambert, r for Phong.
  double lobe_exponent() const { return kind == BrdfKind::Lambert ? 1.0 : phong_exponent; }
};

// The lobe axis: the normal (Lambert) or the mirror direction of `to_viewer`
// about the normal, R = 2(n·v)n − v (Phong). Both arguments unit.
glm::dvec3 lobe_axis(const Brdf& brdf, const glm::dvec3& normal, const glm::dvec3& to_viewer);

// g_r(t) = (r+1)/(2π)·max(t, 0)^r.
double lobe_profile(double r, double t);

// ZH of g_r (Lambert·cos for r = 1, normalised Phong otherwise). Closed form
// through ∫_0^1 t^r P_l = (r−l+2)/(r+l+1)·∫_0^1 t^r P_{l−2}, valid for real r > −1.
sh::Vec lobe_zh(int order, double r);
sh::Vec brdf_zh(int order, const Brdf& brdf);

// ZH of log max(g_r(t), ε) (ε > 0; the whole t ≤ 0 half counts as ε). With
// k₀ = (r+1)/(2π) the lobe crosses ε at t = z₁ = (ε/k₀)^{1/r}; for z₁ ≥ 1 the
// log-lobe is the constant ln ε and only z_0 = √(4π)·ln ε is non-zero.
//
// Closed form (math-notes §7), orders 1…4 only; throws std::invalid_argument above.
sh::Vec log_lobe_zh_closed_form(int order, double r, double epsilon);
// Any order: exact ln ε part (Legendre antiderivative on [−1, z₁]) plus
// Gauss–Legendre on [z₁, 1] split geometrically from z₁ so the ln t singularity
// just left of the kink costs nothing; accurate to ≈1e-13.
sh::Vec log_lobe_zh_quadrature(int order, double r, double epsilon);
// Closed form for order ≤ 4, quadrature above.
sh::Vec log_lobe_zh(int order, double r, double epsilon);
sh::Vec log_brdf_zh(int order, const Brdf& brdf, double epsilon);

}  // namespace skylit::shading
