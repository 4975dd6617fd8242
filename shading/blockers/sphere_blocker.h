// Sphere blockers (aircraft) in SH and log-SH (math-notes §4, §9.7): closed-form
// ZH of the occluded cap, its visibility and log-visibility ZH, culling, and the
// accumulation of many spheres into one log-SH vector by ZH rotation.
#pragma once

#include "shading/sh/sh_basis.h"
#include "shading/sh/sh_exp.h"

#include <span>

namespace skylit::blockers {

struct Sphere {
  glm::dvec3 centre;
  double radius = 0.0;
};

// cos of the cap half-angle asin(min(1, r/d)) a sphere (radius r, centre at
// distance d) subtends; the cap is at most a hemisphere (d ≤ r → 0).
double sphere_cap_cos(double radius, double distance);
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

struct BlockerOptions {
  double epsilon = kDefaultLogEpsilon;  // visibility floor inside a blocker: log ε per sphere
  // LSH: scale each log vector by r/d (ε_eff = ε^{r/d}: isolated spheres turn
  // semi-transparent). Off: with the HYB guards on it gains little (table D).
  bool ratio_attenuation = false;
  // Error target for culling: a sphere is dropped when the bound on the change of
  // the visibility vector, ‖ΔV‖/√(4π) ≤ n·Ω/(4π) (Ω = cap solid angle, n = order,
  // from |y_l0| ≤ √((2l+1)/(4π))), is below it. 0 culls nothing by size.
  double cull_error = 1e-4;
};

enum class Cull { kKeep, kBelowTangentPlane, kTooSmall };

// Why (or whether) a sphere is skipped for receiver p with unit normal n:
// entirely below the tangent plane (n·(c−p) + r ≤ 0), or below the error target.
Cull classify_sphere(const Sphere& s, const glm::dvec3& p, const glm::dvec3& n, int order, const BlockerOptions& opt);
// Smallest cap solid angle that survives culling at this order.
double min_cap_solid_angle(int order, const BlockerOptions& opt);

// Adds the log-visibility of every kept sphere to log_sh (order = √size),
// rotated toward its centre. Returns the number of spheres accumulated.
// No allocation: safe in a per-texel loop.
int accumulate_log_visibility(std::span<const Sphere> spheres, const glm::dvec3& p, const glm::dvec3& n,
                              const BlockerOptions& opt, std::span<double> log_sh);

}  // namespace skylit::blockers
