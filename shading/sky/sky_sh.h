// Projection of a sky model onto RGB spherical harmonics (math-notes §0
// conventions), windowing against ringing, and irradiance from the result.
//
// Quadrature: skies are 0 below the horizon, so the rule covers only the upper
// hemisphere — Gauss–Legendre in z on [0, 1] × midpoint in φ. Splitting at
// z = 0 keeps the horizon discontinuity off the nodes. Skies are smooth except
// for the cusp of the circumsolar term at the sun (e^{Dγ}), which converges
// like a midpoint rule; the default 128 × 256 nodes agree with a 400 × 800
// midpoint θ × φ reference to ≈1e-5 of L_00 at order 8 (sky_sh_test).
// The solar disc is never projected: the models exclude it, and an HDR map's
// sun is clamped at load time (sky_envmap.h).
#pragma once

#include "shading/sh/quadrature.h"
#include "shading/sh/sh_basis.h"
#include "shading/sky/sky_model.h"

#include <array>
#include <vector>

namespace skylit::sky {

inline constexpr int kDenseNz = 128;
inline constexpr int kDenseNphi = 256;

// nz GL nodes in z ∈ [0, 1] × nphi midpoint nodes in φ; weights sum to 2π.
sh::SphereRule upper_hemisphere_rule(int nz, int nphi);

struct RgbSh {
  std::array<sh::Vec, 3> c;  // coefficients of R, G, B; each n² long
  int order() const;
};

// Caches the rule and the basis at its nodes, so re-projecting a changing sky
// (time of day) costs only the radiance evaluations and one accumulation.
class SkyProjector {
 public:
  explicit SkyProjector(int order, int nz = kDenseNz, int nphi = kDenseNphi);
  RgbSh project(const SkyModel& sky) const;
  int order() const { return order_; }

 private:
  int order_;
  sh::SphereRule rule_;
  std::vector<double> basis_;  // n² values per node, node-major
};

// One-off projection (builds a SkyProjector).
RgbSh project_sky(const SkyModel& sky, int order, int nz = kDenseNz, int nphi = kDenseNphi);

// Per-band windows against Gibbs ringing (Sloan, "Stupid SH tricks", 2008),
// width w = order: Hanning h_l = (1 + cos(πl/w))/2; Lanczos σ_l = sinc(πl/w).
// The DC weight is 1, so total flux is kept, but bands 1–2 shrink and with them
// the irradiance (Hanning, order 4: L_1m × 0.854, L_2m × 0.5). Without a window the
// order-4 reconstruction of a clear sky with the sun 5° high dips to −1.3× its
// mean value inside the upper hemisphere; with Hanning it stays > 0 (sky_sh_test).
enum class Window { None, Hanning, Lanczos };
std::vector<double> window_weights(Window w, int order);
void apply_window(RgbSh& s, Window w);

Rgb reconstruct(const RgbSh& s, const glm::dvec3& dir);

// Irradiance ∫ L max(n·ω, 0) dω on a surface with unit normal n, from the SH
// (exact for the order-n band-limited sky: the clamped cosine's ZH, shading/sh/zonal.h,
// rotated to n).
Rgb irradiance(const RgbSh& s, const glm::dvec3& normal);
// Horizontal irradiance of a sky that is 0 below the horizon: there cos θ need not
// be clamped, and cos θ = √(4π/3)·y_10, so E = √(4π/3)·L_10 exactly (order ≥ 2).
Rgb horizontal_irradiance(const RgbSh& s);
// The same directly from the model by quadrature (no SH).
Rgb horizontal_irradiance(const SkyModel& sky, int nz = kDenseNz, int nphi = kDenseNphi);

}  // namespace skylit::sky
