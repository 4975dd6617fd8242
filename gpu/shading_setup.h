// The sky shading of `shaded` and `irradiance` in surface_products.comp, set up as
// compute_product sets up its Shaders (reference_pipeline.cpp: SkyShading, LitShading):
// Lambert, one sky per output channel (unlit: the uniform sky; lit: the lighting's sky
// radiance, R, G, B for a colour `shaded`, else its luminance). Table mode uploads the
// sky × BRDF tables; the SH modes (triple, log-brdf) the sky SH per channel, the
// (log-)lobe ZH as a define and the non-zeros of Γ.
#pragma once

#include "gpu/shader_source.h"
#include "shading/products.h"

#include <cstdint>
#include <vector>

namespace skylit::gpu {

struct ShadingSetup {
  int channels = 1;              // output bands
  std::vector<double> sun_dni;   // lit: the sun's DNI per channel
  // For TABLE_BINDING: the channels' tables back to back (table mode) or the sky SH
  // [c·n² + k] (SH modes). Never empty (GL wants non-empty buffers bound).
  std::vector<float> sky;
  // For GAMMA_BINDING (an RGBA32F buffer texture, SH modes and blockers): per Γ non-zero
  // (i, j, k, value). Never empty.
  std::vector<float> gamma;
};

// Builds the uploads and sets the shading defines of surface_products.comp (see its
// header): SHADING_MODE and MODE_*, SH_BASIS_NORM, CHANNELS, HAS_SKY, TABLE_* /
// TABLE_SIZE (table mode), SKY_SH_BINDING, GAMMA_BINDING, GAMMA_ENTRIES,
// LOBE_ZH_ROTATED, LOG_EPS and the HYB_* of sh_exp.glsl (SH modes). Throws
// std::invalid_argument for log-BRDF options the GPU's HYB does not implement.
ShadingSetup shading_setup(shading::Product product, const shading::ProductOptions& options, int table_binding,
                           int gamma_binding, GlslDefines& defines);

// The sun's DNI per output channel (ShadingSetup::sun_dni): R, G, B, or the luminance.
std::vector<double> channel_dni(const shading::Lighting& lighting, bool rgb);

// What sphere blockers add to a setup (surface_products.comp with BLOCKERS): Γ for
// the SH product V_T ∗ exp*(f_S) and the HYB_* defines of options.blockers.hyb, where
// the shading mode has not set them (the log-BRDF mode adds f_S to its own log and
// needs neither).
void add_blocker_shading(const shading::ProductOptions& options, int gamma_binding, ShadingSetup& setup,
                         GlslDefines& defines);

}  // namespace skylit::gpu
