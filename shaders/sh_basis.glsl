// Real SH basis at a direction, as a ZH rotated toward it: twin of sh::add_rotated_zh
// (sh::eval_basis's associated-Legendre recurrence with the Condon-Shortley phase and
// cos/sin m phi by Chebyshev steps). Needs SH_ORDER, SH_COEFFS and SH_BASIS_NORM
// (float[SH_COEFFS]: sh::sh_norm(l, |m|), times sqrt 2 for m != 0).

int shIndex(int l, int m) { return l * (l + 1) + m; }

// f += sum_l zh[l] y_lm(d), zh[l] already scaled by sqrt(4 pi/(2l+1)).
void addRotatedZh(vec3 d, float zh[SH_ORDER], inout float f[SH_COEFFS]) {
  const float norm[SH_COEFFS] = SH_BASIS_NORM;
  float z = clamp(d.z, -1.0, 1.0);
  float rxy = length(d.xy);
  float c1 = rxy > 0.0 ? d.x / rxy : 1.0, s1 = rxy > 0.0 ? d.y / rxy : 0.0;  // phi undefined at the poles: 0
  float somx2 = sqrt(max(0.0, (1.0 - z) * (1.0 + z)));
  float cm = 1.0, sm = 0.0, pmm = 1.0;
  for (int m = 0; m < SH_ORDER; ++m) {
    float p = pmm, p_prev = 0.0;  // P_l^m, P_{l-1}^m
    for (int l = m; l < SH_ORDER; ++l) {
      if (l > m) {
        float p_next = (float(2 * l - 1) * z * p - float(l + m - 1) * p_prev) / float(l - m);
        p_prev = p;
        p = p_next;
      }
      float y = zh[l] * norm[shIndex(l, m)] * p;
      if (m == 0) {
        f[shIndex(l, 0)] += y;
      } else {
        f[shIndex(l, m)] += y * cm;
        f[shIndex(l, -m)] += y * sm;
      }
    }
    pmm *= -float(2 * m + 1) * somx2;
    float cn = cm * c1 - sm * s1;
    sm = sm * c1 + cm * s1;
    cm = cn;
  }
}
