// Truncated SH product (f*g)_i = sum Gamma_ijk f_j g_k over the non-zeros of
// sh::TripleProduct::entries() (every permutation listed): twin of
// sh::TripleProduct::product. Needs SH_COEFFS, GAMMA_ENTRIES and GAMMA_BINDING (a
// texture unit: on llvmpipe a buffer texture's fetch is a vector gather where a storage
// buffer's load is a scalar loop over the SIMD lanes).

// Entry e: (i, j, k, Gamma_ijk), the indices as exact small floats.
layout(binding = GAMMA_BINDING) uniform samplerBuffer gamma_tex;

void shProduct(float f[SH_COEFFS], float g[SH_COEFFS], out float o[SH_COEFFS]) {
  for (int r = 0; r < SH_COEFFS; ++r) o[r] = 0.0;
  for (int e = 0; e < GAMMA_ENTRIES; ++e) {
    vec4 t = texelFetch(gamma_tex, e);
    o[int(t.x)] += t.w * f[int(t.y)] * g[int(t.z)];
  }
}
