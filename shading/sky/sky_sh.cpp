#include "shading/sky/sky_sh.h"

#include "shading/sh/sh_rotation.h"
#include "shading/sh/zonal.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace skylit::sky {

sh::SphereRule upper_hemisphere_rule(int nz, int nphi) { return sh::sphere_product_rule(nz, nphi, 0.0, 1.0); }

int RgbSh::order() const { return sh::order_of(c[0].size()); }

SkyProjector::SkyProjector(int order, int nz, int nphi) : order_(order), rule_(upper_hemisphere_rule(nz, nphi)) {
  if (order < sh::kMinOrder || order > sh::kMaxOrder) throw std::invalid_argument("SkyProjector: order not in 1..8");
  const std::size_t nc = sh::num_coeffs(order);
  basis_.resize(rule_.dirs.size() * nc);
  for (std::size_t k = 0; k < rule_.dirs.size(); ++k)
    sh::eval_basis(order, rule_.dirs[k], std::span<double>(basis_.data() + k * nc, nc));
}

RgbSh SkyProjector::project(const SkyModel& sky) const {
  const std::size_t nc = sh::num_coeffs(order_);
  RgbSh out;
  for (auto& v : out.c) v.assign(nc, 0.0);
  for (std::size_t k = 0; k < rule_.dirs.size(); ++k) {
    const Rgb L = sky.radiance(rule_.dirs[k]) * rule_.weights[k];
    if (L == Rgb(0.0)) continue;
    const double* y = basis_.data() + k * nc;
    for (int ch = 0; ch < 3; ++ch)
      for (std::size_t i = 0; i < nc; ++i) out.c[ch][i] += L[ch] * y[i];
  }
  return out;
}

RgbSh project_sky(const SkyModel& sky, int order, int nz, int nphi) {
  return SkyProjector(order, nz, nphi).project(sky);
}

std::vector<double> window_weights(Window w, int order) {
  std::vector<double> h(order, 1.0);
  for (int l = 1; l < order; ++l) {
    const double x = sh::kPi * l / order;
    if (w == Window::Hanning) h[l] = 0.5 * (1.0 + std::cos(x));
    if (w == Window::Lanczos) h[l] = std::sin(x) / x;
  }
  return h;
}

void apply_window(RgbSh& s, Window w) {
  const auto h = window_weights(w, s.order());
  for (auto& v : s.c)
    for (std::size_t i = 0; i < v.size(); ++i) v[i] *= h[sh::band_of(static_cast<int>(i))];
}

Rgb reconstruct(const RgbSh& s, const glm::dvec3& dir) {
  const auto y = sh::eval_basis(s.order(), dir);
  return {sh::dot(s.c[0], y), sh::dot(s.c[1], y), sh::dot(s.c[2], y)};
}

Rgb irradiance(const RgbSh& s, const glm::dvec3& normal) {
  const sh::Vec k = sh::rotate_zh(sh::clamped_cosine_zh(s.order()), normal);
  return {sh::dot(s.c[0], k), sh::dot(s.c[1], k), sh::dot(s.c[2], k)};
}

Rgb horizontal_irradiance(const RgbSh& s) {
  if (s.order() < 2) throw std::invalid_argument("horizontal_irradiance: needs order ≥ 2");
  const double k = std::sqrt(4.0 * sh::kPi / 3.0);
  const int i = sh::index(1, 0);
  return {k * s.c[0][i], k * s.c[1][i], k * s.c[2][i]};
}

Rgb horizontal_irradiance(const SkyModel& sky, int nz, int nphi) {
  const auto rule = upper_hemisphere_rule(nz, nphi);
  Rgb e(0.0);
  for (std::size_t k = 0; k < rule.dirs.size(); ++k) e += sky.radiance(rule.dirs[k]) * (rule.weights[k] * rule.dirs[k].z);
  return e;
}

}  // namespace skylit::sky
