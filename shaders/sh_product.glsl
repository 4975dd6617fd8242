// Truncated SH product (f*g)_i = sum Gamma_ijk f_j g_k over the non-zeros of
// sh::TripleProduct::entries() (every permutation listed): twin of
// sh::TripleProduct::product. Needs SH_COEFFS, GAMMA_ENTRIES and GAMMA_BINDING.

// Entry e: indices i | j << 8 | k << 16 (indices < 256) and the value Gamma_ijk.
struct GammaEntry {
  uint ijk;
  float value;
};
layout(std430, binding = GAMMA_BINDING) readonly buffer Gamma { GammaEntry gamma[]; };

void shProduct(float f[SH_COEFFS], float g[SH_COEFFS], out float o[SH_COEFFS]) {
  for (int r = 0; r < SH_COEFFS; ++r) o[r] = 0.0;
  for (int e = 0; e < GAMMA_ENTRIES; ++e) {
    uint ijk = gamma[e].ijk;
    o[ijk & 0xffu] += gamma[e].value * f[(ijk >> 8) & 0xffu] * g[(ijk >> 16) & 0xffu];
  }
}
