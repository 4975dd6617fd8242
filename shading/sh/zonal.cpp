#include "shading/sh/zonal.h"

#include <cmath>
#include <stdexcept>

namespace skylit::sh {

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

Vec clamped_cosine_power_zh(int order, double r, double scale) {
  if (order < kMinOrder || order > kMaxOrder) throw std::invalid_argument("clamped_cosine_power_zh: order out of range");
  if (!(r > -1.0)) throw std::invalid_argument("clamped_cosine_power_zh: exponent must be > -1");
  Vec j(order);
  for (int l = 0; l < order; ++l)
    j[l] = l == 0 ? 1.0 / (r + 1) : l == 1 ? 1.0 / (r + 2) : (r - l + 2) / (r + l + 1) * j[l - 2];
  Vec z(order);
  for (int l = 0; l < order; ++l) z[l] = std::sqrt(kPi * (2 * l + 1)) * scale * j[l];
  return z;
}

Vec clamped_cosine_zh(int order) { return clamped_cosine_power_zh(order, 1.0); }

}  // namespace skylit::sh
