// HYB exp* in float: twin of sh::exp_hyb<float> with the PS2 base (g = 1 + h + h*h/2)
// and renormalisation (the only route the GPU takes; gpu/shading_setup.cpp checks
// the options). Needs SH_COEFFS, SQRT_4PI, HYB_THRESHOLD, HYB_MAX_SQUARINGS,
// HYB_LOG_FLOOR_ON (0/1) and HYB_LOG_FLOOR (sqrt(4 pi) ln eps), HYB_CLAMP_OUTPUT_DC
// (0/1), HYB_OVERFLOW_LOG (ln FLT_MAX - overflow margin) and HYB_FLUSH_LOG
// (ln FLT_MIN + flush margin).
#include "sh_product.glsl"

// g /= g_0/sqrt(4 pi); returns the log of that scale.
float renormalise(inout float g[SH_COEFFS]) {
  float d = g[0] / SQRT_4PI;
  for (int i = 0; i < SH_COEFFS; ++i) g[i] /= d;
  g[0] = SQRT_4PI;
  return log(d);
}

void expHyb(float f[SH_COEFFS], out float o[SH_COEFFS]) {
  // 1. DC isolation; the optional floor on the mean log keeps the shape.
  float f0 = f[0], shape = 1.0;
#if HYB_LOG_FLOOR_ON
  if (f0 < HYB_LOG_FLOOR) {
    shape = HYB_LOG_FLOOR / f0;
    f0 = HYB_LOG_FLOOR;
  }
#endif
  float c = f0 / SQRT_4PI;
  float amax = 0.0;
  for (int i = 1; i < SH_COEFFS; ++i) amax = max(amax, abs(f[i]));
  float unit_norm = 0.0;  // |f^/amax| in [1, n]: no overflow
  if (amax > 0.0) {
    for (int i = 1; i < SH_COEFFS; ++i) unit_norm += (f[i] / amax) * (f[i] / amax);
    unit_norm = sqrt(unit_norm);
  }
  // 2. k = smallest with |f^|/2^k <= threshold, capped; beyond the cap |h| = threshold.
  float mh = shape * amax * unit_norm;
  int k = 0;
  while (mh > HYB_THRESHOLD && k < HYB_MAX_SQUARINGS) {
    mh *= 0.5;
    ++k;
  }
  mh = min(mh, HYB_THRESHOLD);
  float h[SH_COEFFS];
  h[0] = 0.0;
  for (int i = 1; i < SH_COEFFS; ++i) h[i] = amax > 0.0 ? (f[i] / amax) * (mh / unit_norm) : 0.0;
  // 3. PS2 base, 4. k renormalised squarings.
  float g[SH_COEFFS], sq[SH_COEFFS];
  shProduct(h, h, sq);
  for (int i = 0; i < SH_COEFFS; ++i) g[i] = h[i] + 0.5 * sq[i];
  g[0] += SQRT_4PI;
  float log_scale = renormalise(g);
  for (int s = 0; s < k; ++s) {
    shProduct(g, g, sq);
    g = sq;
    log_scale = 2.0 * log_scale + renormalise(g);
  }
  // 5. e^(c + log scale) once, with the output guards.
  float lsum = c + log_scale;
#if HYB_CLAMP_OUTPUT_DC
  lsum = min(lsum, 0.0);
#endif
  float gmax = 0.0;
  for (int i = 0; i < SH_COEFFS; ++i) gmax = max(gmax, abs(g[i]));
  lsum = min(lsum, HYB_OVERFLOW_LOG - log(gmax));
  float e = lsum < HYB_FLUSH_LOG ? 0.0 : exp(lsum);
  for (int i = 0; i < SH_COEFFS; ++i) o[i] = e * g[i];
}
