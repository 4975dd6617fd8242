// Sphere blockers (aircraft) in SH and log-SH (math-notes §4, §9.7): the cap a sphere
// occludes (its closed-form ZH, visibility and log-visibility ZH are sh::cap_zh & co.,
// shading/sh/zonal.h), culling, and the accumulation of many spheres into one log-SH
// vector by ZH rotation.
#pragma once

#include "shading/sh/sh_basis.h"
#include "shading/sh/sh_exp.h"
#include "shading/sh/zonal.h"

#include <span>

namespace skylit::blockers {

struct Sphere {
  glm::dvec3 centre;
  double radius = 0.0;
};

// cos of the cap half-angle asin(min(1, r/d)) a sphere (radius r, centre at
// distance d) subtends; the cap is at most a hemisphere (d ≤ r → 0).
double sphere_cap_cos(double radius, double distance);

// How a sphere's cap becomes a log-visibility vector.
enum class CapLog {
  kProductAlgebra,  // log*(V_cap), the inverse of exp* (cap_log_table.h)
  kPointwise,       // LSH eq. 26: log ε · cap (over-darkens small caps 2.6× at ε = 0.1)
};

struct BlockerOptions {
  CapLog log = CapLog::kProductAlgebra;
  // kPointwise: the visibility floor inside a blocker (log ε per sphere).
  double epsilon = sh::kDefaultLogEpsilon;
  // kProductAlgebra: the clip of log*'s eigenvalues, the most a lone cap can hide: a
  // receiver inside a sphere keeps 1 − clip of the hemisphere's darkening (skyview
  // error 0.034 at 1e-3, 0.12 at 0.1, 0.48 at 0.5: tests/renderer_blockers_test.cpp).
  double log_clip = 1e-3;
  // LSH: scale each log vector by r/d (ε_eff = ε^{r/d}: isolated spheres turn
  // semi-transparent). Off: with the HYB guards on it gains little (table D).
  bool ratio_attenuation = false;
  // Error target for culling: a sphere is dropped when the bound on the change of
  // the visibility vector, ‖ΔV‖/√(4π) ≤ n·Ω/(4π) (Ω = cap solid angle, n = order,
  // from |y_l0| ≤ √((2l+1)/(4π))), is below it. 0 culls nothing by size. The renderer
  // makes it a budget per receiver over whole aircraft (receiver_budget.h). 1e-3 (a
  // quarter of an 8-bit code) meets the skyview targets (RMSE 0.0004, max 0.0007
  // against the truth below a low airliner) at a tenth of 1e-4's area (docs/accuracy.md).
  double cull_error = 1e-3;
};

// Throws std::invalid_argument (one line) for ε ∉ (0, 1) or a negative cull error.
void validate(const BlockerOptions& opt);

enum class Cull { kKeep, kBelowTangentPlane, kTooSmall };

// Why (or whether) a sphere is skipped for receiver p with unit normal n:
// entirely below the tangent plane (n·(c−p) + r ≤ 0), or below the error target.
Cull classify_sphere(const Sphere& s, const glm::dvec3& p, const glm::dvec3& n, int order, const BlockerOptions& opt);
// Smallest cap solid angle that survives culling at this order.
double min_cap_solid_angle(int order, const BlockerOptions& opt);

// Adds the log-visibility of one sphere to log_sh unless classify_sphere culls it
// (returns whether it was added); zh: n doubles of scratch.
bool add_log_visibility(const Sphere& s, const glm::dvec3& p, const glm::dvec3& n, const BlockerOptions& opt,
                        std::span<double> zh, std::span<double> log_sh);

// Adds the log-visibility of every kept sphere to log_sh (order = √size),
// rotated toward its centre. Returns the number of spheres accumulated.
// No allocation: safe in a per-texel loop.
int accumulate_log_visibility(std::span<const Sphere> spheres, const glm::dvec3& p, const glm::dvec3& n,
                              const BlockerOptions& opt, std::span<double> log_sh);

}  // namespace skylit::blockers
