#include "shading/brdf.h"

#include "shading/sh/quadrature.h"
#include "shading/sh/zonal.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <stdexcept>

namespace skylit::shading {
namespace {

void check_order(int order) {
  if (order < sh::kMinOrder || order > sh::kMaxOrder) throw std::invalid_argument("brdf: order out of range");
}

void check_lobe(double r, double epsilon) {
  if (!(r > 0.0)) throw std::invalid_argument("brdf: lobe exponent must be > 0");
  if (!(epsilon > 0.0)) throw std::invalid_argument("brdf: epsilon must be > 0");
}

double zh_scale(int l) { return std::sqrt(sh::kPi * (2 * l + 1)); }

double lobe_peak(double r) { return (r + 1.0) / (2.0 * sh::kPi); }

// ∫_{−1}^{x} P_l(t) dt from (2l+1)P_l = P'_{l+1} − P'_{l−1}.
double legendre_antiderivative(int l, double x) {
  if (l == 0) return 1.0 + x;
  return (sh::legendre(l + 1, x) - sh::legendre(l - 1, x)) / (2 * l + 1);
}

}  // namespace

glm::dvec3 lobe_axis(const Brdf& brdf, const glm::dvec3& normal, const glm::dvec3& to_viewer) {
  if (brdf.kind == BrdfKind::Lambert) return normal;
  return glm::normalize(2.0 * glm::dot(normal, to_viewer) * normal - to_viewer);
}

double lobe_profile(double r, double t) { return t > 0.0 ? lobe_peak(r) * std::pow(t, r) : 0.0; }

sh::Vec lobe_zh(int order, double r) {
  check_order(order);
  check_lobe(r, 1.0);
  return sh::clamped_cosine_power_zh(order, r, lobe_peak(r));
}

sh::Vec brdf_zh(int order, const Brdf& brdf) { return lobe_zh(order, brdf.lobe_exponent()); }

sh::Vec log_lobe_zh_closed_form(int order, double r, double epsilon) {
  if (order > 4) throw std::invalid_argument("log_lobe_zh_closed_form: order ≤ 4 only");
  check_order(order);
  check_lobe(r, epsilon);
  const double k0 = lobe_peak(r), L = std::log(epsilon);
  sh::Vec z(order, 0.0);
  if (epsilon >= k0) {  // z₁ ≥ 1: the lobe never rises above ε
    z[0] = sh::kSqrt4Pi * L;
    return z;
  }
  const double z1 = std::pow(epsilon / k0, 1.0 / r), lz = std::log(z1);
  const double I[4] = {
      std::log(epsilon * k0) - r * (1 - z1),
      -0.5 * r * lz - 0.25 * r * (1 - z1 * z1),
      r * (1 - z1) * (1 - z1) * (z1 + 2) / 6,
      (4 * r * lz + r * (5 * std::pow(z1, 4) - 12 * z1 * z1 + 7)) / 32,
  };
  for (int l = 0; l < order; ++l) z[l] = zh_scale(l) * I[l];
  return z;
}

sh::Vec log_lobe_zh_quadrature(int order, double r, double epsilon) {
  check_order(order);
  check_lobe(r, epsilon);
  const double k0 = lobe_peak(r), L = std::log(epsilon);
  sh::Vec z(order, 0.0);
  if (epsilon >= k0) {
    z[0] = sh::kSqrt4Pi * L;
    return z;
  }
  const double z1 = std::pow(epsilon / k0, 1.0 / r);
  sh::Vec I(order);
  for (int l = 0; l < order; ++l) I[l] = L * legendre_antiderivative(l, z1);
  // ln k₀ + r ln t on [z₁, 1], pieces [z₁·2^k, z₁·2^{k+1}] ∩ [z₁, 1].
  const auto unit = sh::gauss_legendre(24, 0.0, 1.0);
  for (double a = z1; a < 1.0; a *= 2.0) {
    const double b = std::min(1.0, 2.0 * a), len = b - a;
    for (std::size_t q = 0; q < unit.nodes.size(); ++q) {
      const double t = a + len * unit.nodes[q];
      const double w = len * unit.weights[q] * (std::log(k0) + r * std::log(t));
      for (int l = 0; l < order; ++l) I[l] += w * sh::legendre(l, t);
    }
  }
  for (int l = 0; l < order; ++l) z[l] = zh_scale(l) * I[l];
  return z;
}

sh::Vec log_lobe_zh(int order, double r, double epsilon) {
  return order <= 4 ? log_lobe_zh_closed_form(order, r, epsilon) : log_lobe_zh_quadrature(order, r, epsilon);
}

sh::Vec log_brdf_zh(int order, const Brdf& brdf, double epsilon) {
  return log_lobe_zh(order, brdf.lobe_exponent(), epsilon);
}

}  // namespace skylit::shading
