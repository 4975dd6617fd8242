// The three shading modes of DESIGN step 7. Each computes the outgoing radiance
// (albedo 1) ∫ L(ω)·V(ω)·g_r(ω·a) dω of a receiver with SH visibility V under a
// mono sky L, for the reflectance lobe g_r about the axis a of brdf.h (normal for
// Lambert, reflected view direction for Phong). An RGB sky is three calls.
//
//   LogBrdf       (LSH §5)  exp*(V_log + F_log)·L̃: the log-ZH of max(g_r, ε) rotated
//                           to a is added to the log-visibility, exponentiated
//                           (HYB, or pointwise/product-algebra for comparison) and
//                           dotted with the sky SH. One exp*, no separate SH
//                           product; errs by tens of percent (math-notes §7).
//   TripleProduct           (V * F)·L̃ with F = ZH of g_r rotated to a and * the
//                           truncated SH product: band-limits V, g_r and L.
//   SkyBrdfTable  (default) V·T(a) with T the table of sky_brdf_table.h, the SH
//                           projection of the full-frequency L·g_r per axis:
//                           band-limits only V.
//
// Inputs: V is the order-n SH visibility (n² entries) or, for LogBrdf, the
// log-visibility (log ε·occlusion summed over height field and blockers). The sky
// is its order-n SH vector L̃ (LogBrdf, TripleProduct) or its radiance function
// (SkyBrdfTable). Measured accuracy of each mode: docs/numerics.md §3.
#pragma once

#include "shading/brdf.h"
#include "shading/sh/sh_exp.h"
#include "shading/sh/sh_product.h"
#include "shading/sky_brdf_table.h"

#include <memory>
#include <optional>
#include <span>
#include <string_view>

namespace skylit::shading {

enum class ShadingMode { LogBrdf, TripleProduct, SkyBrdfTable };

// "log-brdf", "triple", "table".
std::string_view to_string(ShadingMode mode);
std::optional<ShadingMode> parse_shading_mode(std::string_view name);

// How LogBrdf exponentiates: HYB (the GPU's method), T1 pointwise, T2 expm(M_f)·1.
enum class LogExp { Hyb, Pointwise, ProductAlgebra };

// HYB options for LogBrdf: the exponentiated vector is visibility × BRDF, not a
// visibility, so the visibility guards (output DC ≤ √(4π), log floor) are off.
sh::HybOptions log_brdf_hyb_options();

// ---- Per-texel kernels (no allocation; n = order of the inputs) -------------

// (V * rotate_zh(lobe_zh, axis))·sky_sh with the truncated product of `gamma`.
double shade_triple_product(const sh::TripleProduct& gamma, std::span<const double> visibility,
                            std::span<const double> sky_sh, std::span<const double> lobe_zh, const glm::dvec3& axis);

// exp*(log_visibility + rotate_zh(log_lobe_zh, axis))·sky_sh. Allocates only for
// LogExp::Pointwise / ProductAlgebra.
double shade_log_brdf(std::span<const double> log_visibility, std::span<const double> sky_sh,
                      std::span<const double> log_lobe_zh, const glm::dvec3& axis, LogExp method = LogExp::Hyb,
                      const sh::HybOptions& hyb = log_brdf_hyb_options());

// (The SkyBrdfTable kernel is SkyBrdfTable::shade(V, axis).)

// ---- One object per (mode, BRDF, sky) ---------------------------------------

struct ShadingSettings {
  ShadingMode mode = ShadingMode::SkyBrdfTable;
  int order = sh::kDefaultOrder;
  Brdf brdf;
  // LogBrdf: ε of log max(g_r, ε), and the exponentiation.
  double log_epsilon = 0.05;
  LogExp log_exp = LogExp::Hyb;
  sh::HybOptions log_hyb = log_brdf_hyb_options();
  // shade_log in the other modes exponentiates V_log with these (visibility guards on).
  sh::HybOptions visibility_hyb = {};
  // SkyBrdfTable grid; default: AxisGrid::hemisphere() for Lambert (normals),
  // AxisGrid::sphere() for Phong (reflected directions may point below the horizon).
  std::optional<AxisGrid> table_grid;
  LobeQuadrature table_quadrature;
};

// The grid a setting's table uses.
AxisGrid table_grid_for(const ShadingSettings& settings);

struct SkyInput {
  sh::Vec sh;                // order-n SH of the radiance: LogBrdf, TripleProduct
  Radiance radiance;         // full-frequency radiance: SkyBrdfTable
  bool z_symmetric = false;  // radiance symmetric about z (SkyBrdfTable's shortcut)
  // SkyBrdfTable: the table of `radiance` for the Shader's settings, built already (a
  // colour sky's channels in one pass, SkyBrdfTable::rgb); null: the Shader builds it.
  std::shared_ptr<const SkyBrdfTable> table = nullptr;
};

class Shader {
 public:
  // Throws std::invalid_argument if the sky lacks what the mode needs.
  Shader(const ShadingSettings& settings, const SkyInput& sky);
  // New sky (rebuilds the table in SkyBrdfTable mode).
  void set_sky(const SkyInput& sky);

  const ShadingSettings& settings() const { return settings_; }
  // The table (SkyBrdfTable mode only, else nullptr): its texels() go to the GPU.
  const SkyBrdfTable* table() const { return table_.get(); }
  // The ZH uploaded for the other modes: lobe (TripleProduct) or log-lobe (LogBrdf).
  std::span<const double> lobe_zh() const { return lobe_zh_; }
  std::span<const double> log_lobe_zh() const { return log_lobe_zh_; }

  // Plain SH visibility (TripleProduct, SkyBrdfTable). LogBrdf has no log of a
  // plain vector: throws std::logic_error.
  double shade(std::span<const double> visibility, const glm::dvec3& normal, const glm::dvec3& to_viewer) const;
  // Log-visibility (every mode): LogBrdf adds the log-BRDF before exp*; the
  // other modes exponentiate V_log with settings().visibility_hyb, then shade().
  double shade_log(std::span<const double> log_visibility, const glm::dvec3& normal, const glm::dvec3& to_viewer) const;

 private:
  ShadingSettings settings_;
  const sh::TripleProduct* gamma_ = nullptr;
  sh::Vec sky_sh_, lobe_zh_, log_lobe_zh_;
  std::shared_ptr<const SkyBrdfTable> table_;
};

}  // namespace skylit::shading
