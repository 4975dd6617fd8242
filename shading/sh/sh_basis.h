// Real orthonormal spherical harmonics with the Condon–Shortley phase
// (math-notes §0): index i = l(l+1)+m, "order n" = n bands = n² coefficients.
#pragma once

#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace skylit::sh {

inline constexpr int kDefaultOrder = 4;
inline constexpr int kMinOrder = 1;
inline constexpr int kMaxOrder = 8;
inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kSqrt4Pi = 3.5449077018110320546;  // √(4π): DC of the constant 1

using Vec = std::vector<double>;

constexpr int num_coeffs(int order) { return order * order; }
constexpr int index(int l, int m) { return l * (l + 1) + m; }
constexpr int band_of(int i) {
  int l = 0;
  while ((l + 1) * (l + 1) <= i) ++l;
  return l;
}

// Legendre polynomial P_l(x) by the three-term recurrence.
double legendre(int l, double x);
// Associated Legendre P_l^m(x), m ≥ 0, with the Condon–Shortley phase (−1)^m.
double assoc_legendre(int l, int m, double x);
// Normalisation K_lm = √((2l+1)/(4π)·(l−|m|)!/(l+|m|)!).
double sh_norm(int l, int m);

// All n² basis values at a unit direction.
void eval_basis(int order, const glm::dvec3& dir, std::span<double> out);
Vec eval_basis(int order, const glm::dvec3& dir);
// One basis function y_lm at a unit direction.
double eval_basis_one(int l, int m, const glm::dvec3& dir);

// Σ c_i y_i(dir).
double reconstruct(std::span<const double> coeffs, const glm::dvec3& dir);

// Order n of a vector with n² entries; throws std::invalid_argument otherwise.
int order_of(std::size_t size);

// Unit direction from polar angle θ (from +z) and azimuth φ (from +x toward +y).
glm::dvec3 direction(double theta, double phi);

// The SH vector of the constant function 1: (√(4π), 0, …).
Vec constant_one(int order);

double dot(std::span<const double> a, std::span<const double> b);

}  // namespace skylit::sh
