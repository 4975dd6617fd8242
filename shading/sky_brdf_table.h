// Sky-times-BRDF table (DESIGN step 7, shading mode SkyBrdfTable): for a lobe
// axis a on a grid (the normal for Lambert, the reflected view direction for
// Phong, brdf.h) the SH projection of the full-frequency sky radiance times the
// lobe,
//   T_k(a) = ∫ L(ω)·g_r(ω·a)·y_k(ω) dω,     g_r(t) = (r+1)/(2π)·max(t, 0)^r,
// so that the outgoing radiance of a receiver with SH visibility V is
//   ∫ L·V·g_r dω ≈ Σ_k V_k·T_k(a) = ∫ P_n[V]·L·g_r dω:
// only V is band-limited, neither the sky nor the BRDF. Exact when V is
// band-limited (no occluder: V = 1). Rebuilt whenever the sky changes.
//
// T is computed by quadrature of the radiance function itself, in a frame about
// a: midpoint in the local azimuth, Gauss–Legendre in the polar angle on
// [0, π/2] (the lobe's support), split where the great semicircle crosses the
// horizon z = 0 — sky models are 0 below it (sky_model.h), and a smooth sky is
// integrated just as well.
//
// A sky symmetric about z (declared: a Radiance cannot be inspected) needs one
// projection per θ row: T(Rz(φ)·a) = rotate_z(T(a), φ). Where |a_z| ≥ 0.9 the
// quadrature frame is not carried by Rz (frame_about), so those entries differ
// from a direct build by the quadrature's own error (test: SkyBrdfTable.ZSymmetric*).
//
// Grid and memory layout (the GPU uploads texels() unchanged):
//   axis(i, j) = (sin θ_i cos φ_j, sin θ_i sin φ_j, cos θ_i),
//   θ_i = i·θ_max/(n_theta − 1), i < n_theta  (node-centred, both ends included),
//   φ_j = j·2π/n_phi,           j < n_phi    (periodic).
// One GL_TEXTURE_2D_ARRAY, GL_RGBA32F, width n_phi, height n_theta,
// depth layers = ⌈n²/4⌉; coefficient k sits in layer k/4, channel k%4
// (coefficients ≥ n² are 0):
//   texels()[((layer·n_theta + i)·n_phi + j)·4 + channel] = T_{4·layer+channel}(axis(i, j)).
// Lookup (lookup(), and the GPU with GL_LINEAR, GL_REPEAT in s, GL_CLAMP_TO_EDGE in t):
//   s = φ/(2π) + 0.5/n_phi,   t = (clamp(θ/θ_max, 0, 1)·(n_theta − 1) + 0.5)/n_theta.
// Axes beyond θ_max are clamped to it. Hardware bilinear weights have only
// 8 fractional bits on common GPUs; filter manually (texelFetch) where the
// interpolation must match this CPU lookup. Mono: an RGB sky is three tables.
#pragma once

#include "shading/sh/sh_basis.h"

#include <array>
#include <functional>
#include <memory>
#include <span>
#include <vector>

namespace skylit::shading {

using Radiance = std::function<double(const glm::dvec3& dir)>;
// A colour sky's three channel radiances (R, G, B) of a direction.
using RgbRadiance = std::function<glm::dvec3(const glm::dvec3& dir)>;

// The fixed smooth test sky of math-notes §7/§8 on the whole sphere:
// L(ω) = 0.6 + 0.4·z + 0.8·exp(6(ω·ŝ − 1)), ŝ = test_sky_sun() (elevation 35°,
// math azimuth 40°). Its SH projection is the band-limited test sky L̃.
glm::dvec3 test_sky_sun();
double test_sky_radiance(const glm::dvec3& dir);

struct AxisGrid {
  int n_theta = 33;
  int n_phi = 64;
  double theta_max = sh::kPi / 2;  // π/2: upper hemisphere (normals); π: whole sphere

  // Upper hemisphere (Lambert normals) or whole sphere (Phong reflected directions).
  static AxisGrid hemisphere(int n_theta = 33, int n_phi = 64) { return {n_theta, n_phi, sh::kPi / 2}; }
  static AxisGrid sphere(int n_theta = 65, int n_phi = 128) { return {n_theta, n_phi, sh::kPi}; }
  double theta(int i) const { return theta_max * i / (n_theta - 1); }
  double phi(int j) const { return 2.0 * sh::kPi * j / n_phi; }
  glm::dvec3 axis(int i, int j) const;
};

struct LobeQuadrature {
  int azimuths = 64;     // midpoint rule in the azimuth about the lobe axis
  int gauss_nodes = 16;  // Gauss–Legendre nodes per polar piece (one or two pieces)
};

// T(a) for one axis, no grid: the quantity the table samples.
sh::Vec sky_lobe_projection(int order, double lobe_exponent, const Radiance& sky, const glm::dvec3& axis,
                            const LobeQuadrature& quad = {});

class SkyBrdfTable {
 public:
  // order in [1, sh::kMaxOrder], lobe_exponent r > 0 (1 = Lambert), n_theta ≥ 2,
  // n_phi ≥ 1, θ_max in (0, π]; throws std::invalid_argument otherwise. Rows are
  // built on all hardware threads: `sky` must be safe to call concurrently.
  // z_symmetric: the caller vouches that sky(Rz·ω) = sky(ω) for every rotation Rz
  // about z; rows are then one projection rotated along φ (≈n_phi× faster).
  SkyBrdfTable(int order, double lobe_exponent, const Radiance& sky, const AxisGrid& grid,
               const LobeQuadrature& quad = {}, bool z_symmetric = false);
  // The tables of a colour sky's R, G and B, equal to three tables built from its
  // channels one at a time (the same sums, term for term) at a third of the sky's and
  // the basis' evaluations.
  static std::array<std::shared_ptr<const SkyBrdfTable>, 3> rgb(int order, double lobe_exponent,
                                                                const RgbRadiance& sky, const AxisGrid& grid,
                                                                const LobeQuadrature& quad = {},
                                                                bool z_symmetric = false);

  int order() const { return order_; }
  double lobe_exponent() const { return lobe_exponent_; }
  const AxisGrid& grid() const { return grid_; }
  int layers() const { return (sh::num_coeffs(order_) + 3) / 4; }
  // Offset of (layer, i, j, channel) in values() / texels().
  std::size_t texel_index(int layer, int i, int j, int channel) const {
    return ((static_cast<std::size_t>(layer) * grid_.n_theta + i) * grid_.n_phi + j) * 4 + channel;
  }
  std::span<const double> values() const { return values_; }  // double, CPU reference
  std::span<const float> texels() const { return texels_; }   // the same, float, for upload

  // Bilinear T(a) (see the header comment); out.size() = n². No allocation.
  void lookup(const glm::dvec3& axis, std::span<double> out) const;
  sh::Vec lookup(const glm::dvec3& axis) const;
  // Outgoing radiance Σ_k V_k·T_k(a) (albedo 1); visibility has n² entries.
  double shade(std::span<const double> visibility, const glm::dvec3& axis) const;

 private:
  SkyBrdfTable(int order, double lobe_exponent, const AxisGrid& grid);  // checked, zero values
  // Every row of the C tables (same order and grid), project(axis) giving T(axis) of
  // each, on all hardware threads; then their texels.
  template <std::size_t C, class Project>
  static void fill(const std::array<SkyBrdfTable*, C>& tables, bool z_symmetric, const Project& project);

  int order_;
  double lobe_exponent_;
  AxisGrid grid_;
  std::vector<double> values_;
  std::vector<float> texels_;
};

}  // namespace skylit::shading
