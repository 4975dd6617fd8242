// The reference exponentials of a log-SH vector f (math-notes §6), against which HYB
// (sh_exp.h) is judged and its optimal-linear table (hyb_table.h) is fitted:
//  * T1 exp_pointwise: P_n[exp(Σ f_i y_i)] by quadrature (the band-limited exp*);
//  * T2 exp_product_algebra: expm(M_f)·1, the exponential in the truncated-product
//    algebra, which HYB approximates (the product is not associative, §5).
#pragma once

#include "shading/sh/sh_basis.h"

#include <span>

namespace skylit::sh {

// T1 on an nz × nphi product grid (GL in z × midpoint in φ). The defaults
// converge to ≤ 1e-11 relative for order ≤ 4 and |f| in the hundreds (§6.1).
Vec exp_pointwise(std::span<const double> f, int nz = 96, int nphi = 192);
// T1 of a ZH vector (z_0 … z_{n−1}) by GL in z; the result is ZH too.
Vec exp_pointwise_zh(std::span<const double> zh, int nodes = 64);

// T2 = expm(M_f)·1 by the eigendecomposition of the symmetric M_f̂ (cyclic
// Jacobi), shifted by its largest eigenvalue so nothing overflows before the
// final scale e^{f_0/√(4π) + λ_max}.
Vec exp_product_algebra(std::span<const double> f);

// Its inverse on a visibility vector v (Ren et al. 2006's log*): log(M_v)·1 by the same
// eigendecomposition, eigenvalues clipped at `floor` > 0 (band-limited visibility can
// dip to or below 0, where no log exists): exp_product_algebra(log_product_algebra(v))
// = v wherever M_v's eigenvalues are ≥ floor.
Vec log_product_algebra(std::span<const double> v, double floor);

}  // namespace skylit::sh
