#include "gpu/shading_setup.h"

#include "shading/lighting.h"
#include "shading/reference_pipeline.h"
#include "shading/sh/sh_exp.h"
#include "shading/sh/sh_product.h"
#include "shading/sh/sh_rotation.h"
#include "shading/shading_modes.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

namespace skylit::gpu {
namespace {

using shading::ShadingMode;

// sh_norm(l, |m|) per coefficient, √2 folded in for m ≠ 0 (sh::eval_basis).
std::vector<double> basis_norm(int order) {
  std::vector<double> out;
  for (int l = 0; l < order; ++l)
    for (int m = -l; m <= l; ++m) out.push_back(sh::sh_norm(l, m) * (m == 0 ? 1.0 : std::sqrt(2.0)));
  return out;
}

// sh::zh_rotation_factor(l)·z_l: the factor of y_lm(axis) in sh::add_rotated_zh.
std::vector<double> rotated_zh_factors(std::span<const double> zh) {
  std::vector<double> out;
  for (std::size_t l = 0; l < zh.size(); ++l) out.push_back(sh::zh_rotation_factor(static_cast<int>(l)) * zh[l]);
  return out;
}

void set_hyb_defines(const sh::HybOptions& o, GlslDefines& d) {
  if (o.base != sh::HybBase::kTaylor2 || !o.renormalise)
    throw std::invalid_argument("GPU log-brdf shading: HYB needs the PS2 base with renormalisation");
  const bool floor_on = o.log_floor_epsilon > 0.0;
  d.set("HYB_THRESHOLD", o.threshold)
      .set("HYB_MAX_SQUARINGS", std::clamp(o.max_squarings, 0, sh::kHybSquaringsCap))
      .set("HYB_LOG_FLOOR_ON", floor_on ? 1 : 0)
      .set("HYB_LOG_FLOOR", floor_on ? sh::kSqrt4Pi * std::log(o.log_floor_epsilon) : 0.0)
      .set("HYB_CLAMP_OUTPUT_DC", o.clamp_output_dc ? 1 : 0)
      .set("HYB_OVERFLOW_LOG", std::log(static_cast<double>(std::numeric_limits<float>::max())) - sh::kHybOverflowMargin)
      .set("HYB_FLUSH_LOG", std::log(static_cast<double>(std::numeric_limits<float>::min())) + sh::kHybFlushMargin);
}

// Γ's non-zeros for GAMMA_BINDING, and the defines of sh_product.glsl and sh_exp.glsl's √(4π).
void add_gamma(int order, int gamma_binding, ShadingSetup& out, GlslDefines& d) {
  for (const sh::TripleEntry& e : sh::triple_product(order).entries()) {
    for (double v : {static_cast<double>(e.i), static_cast<double>(e.j), static_cast<double>(e.k), e.value})
      out.gamma.push_back(static_cast<float>(v));
  }
  d.set("GAMMA_BINDING", gamma_binding)
      .set("GAMMA_ENTRIES", static_cast<int>(out.gamma.size() / 4))
      .set("SQRT_4PI", sh::kSqrt4Pi);
}

}  // namespace

std::vector<double> channel_dni(const shading::Lighting& lighting, bool rgb) {
  if (!rgb) return {sky::luminance(lighting.sun.dni)};
  return {lighting.sun.dni[0], lighting.sun.dni[1], lighting.sun.dni[2]};
}

void add_blocker_shading(const shading::ProductOptions& options, int gamma_binding, ShadingSetup& setup,
                         GlslDefines& d) {
  const ShadingMode mode = options.shaded.mode;
  if (mode == ShadingMode::LogBrdf) return;
  if (mode == ShadingMode::SkyBrdfTable) {
    setup.gamma.clear();  // the placeholder
    add_gamma(options.shaded.sh_order, gamma_binding, setup, d);
  }
  set_hyb_defines(options.blockers.hyb, d);
}

ShadingSetup shading_setup(shading::Product product, const shading::ProductOptions& options, int table_binding,
                           int gamma_binding, GlslDefines& d) {
  const shading::ShadedOptions& s = options.shaded;
  const ShadingMode mode = s.mode;
  const bool lit = shading::uses_lighting(product, options);
  ShadingSetup out;
  // The skies, as the reference's SkyShading / LitShading build them (same symmetry
  // flag too: the GPU's table must be the reference's, texel for texel).
  std::vector<shading::SkyInput> skies;
  if (lit) {
    const shading::Lighting& l = *options.lighting;
    const bool rgb = shading::rgb_bands(product, options);
    out.channels = rgb ? 3 : 1;
    out.sun_dni = channel_dni(l, rgb);
    skies = shading::channel_sky_inputs(l, rgb, mode, s.sh_order);
  } else {
    skies.push_back(shading::sky_input(mode, s.sh_order, shading::uniform_sky_radiance(), true));
  }
  const shading::ShadingSettings settings = shading::sky_shading_settings(mode, s.sh_order);
  std::vector<std::unique_ptr<shading::Shader>> shaders;
  std::vector<sh::Vec> sky_sh;
  for (const shading::SkyInput& in : skies) {
    if (mode != ShadingMode::SkyBrdfTable) sky_sh.push_back(in.sh);
    shaders.push_back(std::make_unique<shading::Shader>(settings, in));
  }

  d.set("MODE_TABLE", static_cast<int>(ShadingMode::SkyBrdfTable))
      .set("MODE_TRIPLE", static_cast<int>(ShadingMode::TripleProduct))
      .set("MODE_LOG_BRDF", static_cast<int>(ShadingMode::LogBrdf))
      .set("SHADING_MODE", static_cast<int>(mode))
      .set_literal("SH_BASIS_NORM", glsl_float_array_literal(basis_norm(s.sh_order)))
      .set("TABLE_BINDING", table_binding);
  if (lit) d.set("CHANNELS", out.channels).set("HAS_SKY", skies.empty() ? 0 : 1);

  if (mode == ShadingMode::SkyBrdfTable) {
    // The grid is the default mode's either way; without a sky the lookup is unused.
    const shading::AxisGrid grid =
        shaders.empty() ? shading::table_grid_for(settings) : shaders[0]->table()->grid();
    std::size_t table_size = 1;
    for (const auto& sh : shaders) out.sky.insert(out.sky.end(), sh->table()->texels().begin(), sh->table()->texels().end());
    if (!shaders.empty()) table_size = shaders[0]->table()->texels().size();
    d.set("TABLE_N_THETA", grid.n_theta).set("TABLE_N_PHI", grid.n_phi).set("TABLE_THETA_MAX", grid.theta_max);
    d.set("TABLE_LAYERS", shaders.empty() ? 1 : shaders[0]->table()->layers());
    if (lit) d.set("TABLE_SIZE", static_cast<int>(table_size));
  } else {
    for (const sh::Vec& v : sky_sh)
      for (double x : v) out.sky.push_back(static_cast<float>(x));
    // The lobe ZH does not depend on the sky: Lambert, from a Shader as the reference has it.
    const shading::Shader lobe_shader(settings,
                                      shading::sky_input(mode, s.sh_order, shading::uniform_sky_radiance(), true));
    const std::span<const double> zh = mode == ShadingMode::LogBrdf ? lobe_shader.log_lobe_zh() : lobe_shader.lobe_zh();
    add_gamma(s.sh_order, gamma_binding, out, d);
    d.set("SKY_SH_BINDING", table_binding)
        .set_literal("LOBE_ZH_ROTATED", glsl_float_array_literal(rotated_zh_factors(zh)));
    if (mode == ShadingMode::LogBrdf) {
      d.set("LOG_EPS", std::log(sh::kDefaultLogEpsilon));
      set_hyb_defines(settings.log_hyb, d);
    }
  }
  if (out.sky.empty()) out.sky.assign(4, 0.0f);  // GL wants non-empty buffers (one rgba texel)
  if (out.gamma.empty()) out.gamma.assign(4, 0.0f);
  return out;
}

}  // namespace skylit::gpu
