// Sky shading of the SH modes (shading/shading_modes.h) for one texel: the lobe ZH
// rotated to the axis, then
//   MODE_TRIPLE   (V * F).L_c          twin of shading::shade_triple_product
//   MODE_LOG_BRDF exp*(V_log + F_log).L_c  twin of shading::shade_log_brdf (HYB)
// L_c the sky SH of channel c. Needs SHADING_MODE, MODE_TRIPLE, MODE_LOG_BRDF,
// SKY_SH_BINDING, LOBE_ZH_ROTATED (float[SH_ORDER]: sqrt(4 pi/(2l+1)) times
// Shader::lobe_zh() or log_lobe_zh()) and the defines of the included files.
#include "sh_basis.glsl"
#include "sh_product.glsl"
#if SHADING_MODE == MODE_LOG_BRDF
#include "sh_exp.glsl"
#endif

// Sky SH of channel c at [c*SH_COEFFS + k].
layout(std430, binding = SKY_SH_BINDING) readonly buffer SkySh { float sky_sh[]; };

float skyDot(float v[SH_COEFFS], int channel) {
  float s = 0.0;
  for (int k = 0; k < SH_COEFFS; ++k) s += v[k] * sky_sh[channel * SH_COEFFS + k];
  return s;
}

// The channel-independent factor: V * F (triple) or exp*(V_log + F_log) (log-BRDF);
// the shading of channel c is then skyDot(result, c).
void shadedTransfer(float vis[SH_COEFFS], vec3 axis, out float transfer[SH_COEFFS]) {
  const float lobe[SH_ORDER] = LOBE_ZH_ROTATED;
#if SHADING_MODE == MODE_TRIPLE
  float f[SH_COEFFS];
  for (int k = 0; k < SH_COEFFS; ++k) f[k] = 0.0;
  addRotatedZh(axis, lobe, f);
  shProduct(vis, f, transfer);
#else
  float s[SH_COEFFS] = vis;
  addRotatedZh(axis, lobe, s);
  expHyb(s, transfer);
#endif
}
