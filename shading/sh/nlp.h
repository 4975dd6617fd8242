// Normalized Legendre polynomial (NLP) basis and the per-azimuth slice vectors
// of horizon visibility (NS09 §4, LSH eqs. 14–16; math-notes §2).
//
// P̂_l(z) = √((2l+1)/2)·P_l(z) is orthonormal on [−1, 1], z = cos θ = sin e.
// A slice with horizon elevation σ is occluded for z ≤ sin σ — the whole lower
// hemisphere included, for every σ — so its occlusion coefficients are
// o_l = ∫_{−1}^{sin σ} P̂_l(z) dz and its visibility is (√2, 0, …) − o.
// σ is an elevation (radians above the horizontal), clamped to [−π/2, π/2];
// it is never Max's horizon angle π/2 − σ (math-notes §10.5).
// √(2π)·visibility is the ZH vector of the cap {e > σ}.
#pragma once

#include "shading/sh/sh_basis.h"

#include <span>

namespace skylit::sh {

// √((2l+1)/2): the NLP normalisation.
double nlp_norm(int l);
// P̂_l(z).
double nlp_basis_one(int l, double z);
// P̂_0(z) … P̂_{N−1}(z) with N = out.size().
void nlp_basis(double z, std::span<double> out);
Vec nlp_basis(int nlp_order, double z);

// Occlusion slice o_l, l < out.size(). Closed form, any order, without the
// cancellation of P_{l+1} − P_{l−1} near σ = ±π/2:
//   o_0 = (1 + sin σ)/√2,  o_l = √((2l+1)/2)·(P_{l+1}(s) − P_{l−1}(s))/(2l+1)
//                              = −√((2l+1)/2)·cos²σ·P_l'(s)/(l(l+1)).
void nlp_occlusion(double sigma, std::span<double> out);
Vec nlp_occlusion(int nlp_order, double sigma);

// Visibility slice (√2, 0, …) − o(σ) (NS09 eq. 11).
void nlp_visibility(double sigma, std::span<double> out);
Vec nlp_visibility(int nlp_order, double sigma);

// Log-visibility slice log ε · o(σ) (LSH eqs. 15–16); log_eps < 0.
void nlp_log_visibility(double sigma, double log_eps, std::span<double> out);
Vec nlp_log_visibility(int nlp_order, double sigma, double log_eps);

}  // namespace skylit::sh
