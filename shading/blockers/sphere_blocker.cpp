#include "shading/blockers/sphere_blocker.h"

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

double cap_solid_angle(double cos_alpha) { return 2.0 * kPi * (1.0 - cos_alpha); }

void cap_zh(double c, std::span<double> out) {
  const int order = static_cast<int>(out.size());
  if (order < kMinOrder || order > kMaxOrder) throw std::invalid_argument("cap_zh: order out of range");
  // ∫_c^1 P_l = (P_{l−1}(c) − P_{l+1}(c))/(2l+1); P_l by the three-term recurrence.
  double p_prev = 1.0, p = c;  // P_0, P_1
  out[0] = std::sqrt(kPi) * (1.0 - c);
  for (int l = 1; l < order; ++l) {
    const double p_next = ((2 * l + 1) * c * p - l * p_prev) / (l + 1);
    out[l] = std::sqrt(kPi * (2 * l + 1)) * (p_prev - p_next) / (2 * l + 1);
    p_prev = p;
    p = p_next;
  }
}

Vec cap_zh(int order, double cos_alpha) {
  Vec z(order);
  cap_zh(cos_alpha, z);
  return z;
}

Vec cap_visibility_zh(int order, double cos_alpha) {
  Vec z = cap_zh(order, cos_alpha);
  for (double& v : z) v = -v;
  z[0] += kSqrt4Pi;
  return z;
}

Vec cap_log_visibility_zh(int order, double cos_alpha, double epsilon, double attenuation) {
  Vec z = cap_zh(order, cos_alpha);
  const double k = std::log(epsilon) * attenuation;
  for (double& v : z) v *= k;
  return z;
}

double min_cap_solid_angle(int order, const BlockerOptions& opt) {
  return 4.0 * kPi * opt.cull_error / order;
}

Cull classify_sphere(const Sphere& s, const glm::dvec3& p, const glm::dvec3& n, int order, const BlockerOptions& opt) {
  const glm::dvec3 to_c = s.centre - p;
  if (glm::dot(n, to_c) + s.radius <= 0.0) return Cull::kBelowTangentPlane;
  const double omega = cap_solid_angle(sphere_cap_cos(s.radius, glm::length(to_c)));
  if (omega < min_cap_solid_angle(order, opt)) return Cull::kTooSmall;
  return Cull::kKeep;
}

int accumulate_log_visibility(std::span<const Sphere> spheres, const glm::dvec3& p, const glm::dvec3& n,
                              const BlockerOptions& opt, std::span<double> log_sh) {
  const int order = order_of(log_sh.size());
  if (order > kMaxOrder) throw std::invalid_argument("accumulate_log_visibility: order out of range");
  if (!(opt.epsilon > 0.0 && opt.epsilon < 1.0))
    throw std::invalid_argument("accumulate_log_visibility: epsilon must be in (0, 1)");
  const double log_eps = std::log(opt.epsilon);
  const double min_omega = min_cap_solid_angle(order, opt);
  std::array<double, kMaxOrder> zh{};
  const std::span<double> z(zh.data(), order);
  int kept = 0;
  for (const Sphere& s : spheres) {
    const glm::dvec3 to_c = s.centre - p;
    if (glm::dot(n, to_c) + s.radius <= 0.0) continue;  // entirely below the tangent plane
    const double d = glm::length(to_c);
    const double c = sphere_cap_cos(s.radius, d);
    if (cap_solid_angle(c) < min_omega) continue;  // too small/far to matter
    // Receiver at the centre: the cap is a hemisphere and its axis is undefined; use n.
    const glm::dvec3 axis = d > 0.0 ? to_c / d : n;
    const double atten = opt.ratio_attenuation ? std::min(1.0, s.radius / d) : 1.0;
    cap_zh(c, z);
    add_rotated_zh(z, axis, log_eps * atten, log_sh);
    ++kept;
  }
  return kept;
}

}  // namespace skylit::blockers
