// The wedge assembly V = Σ_j Rz(φ_j) · M · [v_{j+first_tap} ; …] (shading/sh/wedge.h)
// regrouped for surface_products.comp. φ_j = j·Δφ are uniform and M is the same for
// every wedge, so V depends on the slices only through their Fourier sums
//   C_m[l'] = Σ_k cos(m φ_k) v_k[l'],   S_m[l'] = Σ_k sin(m φ_k) v_k[l'],   0 ≤ m < n,
// and V = G · (C, S), G fixed per operator: the kernel accumulates (2n−1)·N sums per
// slice and applies G once per texel, instead of M and Rz once per wedge.
#pragma once

#include "shading/sh/wedge.h"

#include <vector>

namespace skylit::gpu {

// G row-major, n² rows × 2N columns: row r = sh::index(l, m) multiplies
// C_|m| with columns 0 … N−1 and S_|m| with columns N … 2N−1 (zero for m = 0).
// Entries that are rounding residues of exact zeros are exactly 0.
std::vector<double> wedge_fourier_matrix(const sh::WedgeOperator& op);

}  // namespace skylit::gpu
