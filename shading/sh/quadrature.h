// Quadrature rules: Gauss–Legendre on [a, b], and the product rule on the sphere
// (Gauss–Legendre in z = cos θ × midpoint in φ), exact for band-limited
// integrands of z-degree ≤ 2·nz−1 and φ-degree < nphi (math-notes §1).
#pragma once

#include "shading/sh/sh_basis.h"

#include <functional>
#include <vector>

namespace skylit::sh {

struct Rule1D {
  std::vector<double> nodes;
  std::vector<double> weights;
};

// n-point Gauss–Legendre rule on [a, b] (Newton on P_n; accurate to rounding).
Rule1D gauss_legendre(int n, double a = -1.0, double b = 1.0);

struct SphereRule {
  std::vector<glm::dvec3> dirs;
  std::vector<double> weights;  // sum to 4π
};

// nz Gauss–Legendre nodes in z ∈ [z_min, z_max] × nphi midpoint nodes in φ
// (z ∈ [0, 1]: the upper hemisphere, for integrands cut at the horizon).
SphereRule sphere_product_rule(int nz, int nphi, double z_min = -1.0, double z_max = 1.0);
// A rule exact for products of three SH functions of the given order.
SphereRule sphere_rule_for_order(int order);

// SH projection ∫ f y_i dω by the given rule.
sh::Vec project(int order, const SphereRule& rule, const std::function<double(const glm::dvec3&)>& f);
// Projection of a smooth function with a rule fine enough for ≈1e-12 on smooth f.
sh::Vec project_smooth(int order, const std::function<double(const glm::dvec3&)>& f, int nz = 64,
                       int nphi = 128);

}  // namespace skylit::sh
