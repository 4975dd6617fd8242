#include "shading/sh/nlp.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace skylit::sh {

double nlp_norm(int l) { return std::sqrt((2 * l + 1) / 2.0); }

double nlp_basis_one(int l, double z) { return nlp_norm(l) * legendre(l, z); }

void nlp_basis(double z, std::span<double> out) {
  double p_prev = 0.0, p = 1.0;  // P_{l−1}, P_l
  for (std::size_t l = 0; l < out.size(); ++l) {
    out[l] = nlp_norm(static_cast<int>(l)) * p;
    const double k = static_cast<double>(l);
    const double p_next = ((2 * k + 1) * z * p - k * p_prev) / (k + 1);
    p_prev = p;
    p = p_next;
  }
}

Vec nlp_basis(int nlp_order, double z) {
  Vec out(nlp_order);
  nlp_basis(z, out);
  return out;
}

namespace {

// √((2l+1)/2)/(l(l+1)), the factor of the closed form below, tabulated once.
double occlusion_factor(std::size_t l) {
  static const auto table = [] {
    std::array<double, 64> t{};
    for (std::size_t k = 1; k < t.size(); ++k) t[k] = nlp_norm(static_cast<int>(k)) / static_cast<double>(k * (k + 1));
    return t;
  }();
  if (l < table.size()) return table[l];
  return nlp_norm(static_cast<int>(l)) / (static_cast<double>(l) * static_cast<double>(l + 1));
}

}  // namespace

void nlp_occlusion(double sigma, std::span<double> out) {
  if (out.empty()) return;
  const double e = std::clamp(sigma, -std::numbers::pi / 2, std::numbers::pi / 2);
  const double s = std::sin(e), c = std::cos(e), c2 = c * c;
  out[0] = (1.0 + s) / std::numbers::sqrt2;
  // P_l and P_l' by recurrence: P'_{l+1} = P'_{l−1} + (2l+1)·P_l.
  double p_prev = 1.0, p = s;      // P_{l−1}, P_l at l = 1
  double dp_prev = 0.0, dp = 1.0;  // P'_{l−1}, P'_l at l = 1
  for (std::size_t l = 1; l < out.size(); ++l) {
    const double k = static_cast<double>(l);
    out[l] = -occlusion_factor(l) * c2 * dp;
    const double p_next = ((2 * k + 1) * s * p - k * p_prev) / (k + 1);
    const double dp_next = dp_prev + (2 * k + 1) * p;
    p_prev = p;
    p = p_next;
    dp_prev = dp;
    dp = dp_next;
  }
}

Vec nlp_occlusion(int nlp_order, double sigma) {
  Vec out(nlp_order);
  nlp_occlusion(sigma, out);
  return out;
}

void nlp_visibility(double sigma, std::span<double> out) {
  nlp_occlusion(sigma, out);
  for (double& o : out) o = -o;
  if (!out.empty()) out[0] += std::numbers::sqrt2;
}

Vec nlp_visibility(int nlp_order, double sigma) {
  Vec out(nlp_order);
  nlp_visibility(sigma, out);
  return out;
}

void nlp_log_visibility(double sigma, double log_eps, std::span<double> out) {
  nlp_occlusion(sigma, out);
  for (double& o : out) o *= log_eps;
}

Vec nlp_log_visibility(int nlp_order, double sigma, double log_eps) {
  Vec out(nlp_order);
  nlp_log_visibility(sigma, log_eps, out);
  return out;
}

}  // namespace skylit::sh
