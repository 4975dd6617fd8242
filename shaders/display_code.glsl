// 8-bit display code (1 ... 255) of a linear display value: twin of
// shading::display_code_value (sRGB or linear tone curve). Needs SRGB_LINEAR_LIMIT,
// SRGB_LINEAR_SLOPE, SRGB_SCALE, SRGB_OFFSET, SRGB_GAMMA, FIRST_CODE, CODE_SPAN
// (shading/products.h).

float displayCode(float linear, bool srgb) {
  float x = clamp(linear, 0.0, 1.0);
  if (srgb) x = x <= SRGB_LINEAR_LIMIT ? SRGB_LINEAR_SLOPE * x : SRGB_SCALE * pow(x, 1.0 / SRGB_GAMMA) - SRGB_OFFSET;
  return FIRST_CODE + round(CODE_SPAN * x);
}
