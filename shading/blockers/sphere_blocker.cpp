#include "shading/blockers/sphere_blocker.h"

#include "shading/blockers/cap_log_table.h"
#include "shading/sh/sh_rotation.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace skylit::blockers {

double sphere_cap_cos(double radius, double distance) {
  if (!(radius > 0.0)) return 1.0;     // no sphere, no cap
  if (!(distance > radius)) return 0.0;  // inside or touching: a hemisphere
  const double s = radius / distance;
  return std::sqrt((1.0 - s) * (1.0 + s));
}

double min_cap_solid_angle(int order, const BlockerOptions& opt) { return 4.0 * sh::kPi * opt.cull_error / order; }

Cull classify_sphere(const Sphere& s, const glm::dvec3& p, const glm::dvec3& n, int order, const BlockerOptions& opt) {
  const glm::dvec3 to_c = s.centre - p;
  if (glm::dot(n, to_c) + s.radius <= 0.0) return Cull::kBelowTangentPlane;
  const double omega = sh::cap_solid_angle(sphere_cap_cos(s.radius, glm::length(to_c)));
  if (omega < min_cap_solid_angle(order, opt)) return Cull::kTooSmall;
  return Cull::kKeep;
}

bool add_log_visibility(const Sphere& s, const glm::dvec3& p, const glm::dvec3& n, const BlockerOptions& opt,
                        std::span<double> zh, std::span<double> log_sh) {
  const glm::dvec3 to_c = s.centre - p;
  if (glm::dot(n, to_c) + s.radius <= 0.0) return false;  // entirely below the tangent plane
  const double d = glm::length(to_c);
  const double c = sphere_cap_cos(s.radius, d);
  if (sh::cap_solid_angle(c) < min_cap_solid_angle(static_cast<int>(zh.size()), opt))
    return false;  // too small/far
  // Receiver at the centre: the cap is a hemisphere and its axis is undefined; use n.
  const glm::dvec3 axis = d > 0.0 ? to_c / d : n;
  const double ratio = d > s.radius ? s.radius / d : 1.0;
  const double atten = opt.ratio_attenuation ? ratio : 1.0;
  if (opt.log == CapLog::kProductAlgebra) {
    cap_log_table(static_cast<int>(zh.size()), opt.log_clip).log_zh(ratio, zh);
    sh::add_rotated_zh(zh, axis, atten, log_sh);
  } else {
    sh::cap_zh(c, zh);
    sh::add_rotated_zh(zh, axis, std::log(opt.epsilon) * atten, log_sh);
  }
  return true;
}

void validate(const BlockerOptions& opt) {
  if (!(opt.epsilon > 0.0 && opt.epsilon < 1.0)) throw std::invalid_argument("sphere blockers: epsilon must be in (0, 1)");
  if (!(opt.log_clip > 0.0 && opt.log_clip < 1.0))
    throw std::invalid_argument("sphere blockers: the log clip must be in (0, 1)");
  if (!(opt.cull_error >= 0.0) || !std::isfinite(opt.cull_error))
    throw std::invalid_argument("sphere blockers: the cull error must be finite and ≥ 0");
}

int accumulate_log_visibility(std::span<const Sphere> spheres, const glm::dvec3& p, const glm::dvec3& n,
                              const BlockerOptions& opt, std::span<double> log_sh) {
  const int order = sh::order_of(log_sh.size());
  if (order > sh::kMaxOrder) throw std::invalid_argument("accumulate_log_visibility: order out of range");
  validate(opt);
  std::array<double, sh::kMaxOrder> zh{};
  const std::span<double> z(zh.data(), order);
  int kept = 0;
  for (const Sphere& s : spheres) kept += add_log_visibility(s, p, n, opt, z, log_sh) ? 1 : 0;
  return kept;
}

}  // namespace skylit::blockers
