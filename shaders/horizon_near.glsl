// Horizon sweep, per texel (shading/horizon/horizon_sweep.h): the NEAR_STEPS half-texel steps
// of the texel's own ray (as the exact march takes them) and the far slope its owner
// line found; a ray leaving the grid among them (the first step is always checked)
// takes no far field. GLSL twin of horizon::sweep_max_elevation, before its atan.
//
// Needs horizon_ray.glsl (included first) and NEAR_STEPS, INV_TWO_R_EFF,
// FAR_CODE_HALF_RANGE.

// horizon::decode_far_slope: code 0 is none (-inf).
float decodeFarSlope(uint code) {
  if (code == 0u) return uintBitsToFloat(0xff800000u);
  float x = float(code) / float(FAR_CODE_HALF_RANGE) - 1.0;
  return x / (1.0 - abs(x));
}

// Steepest slope (tan of the raw horizon) from texel (i, j) along u; -inf: none.
float sweptSlope(int i, int j, vec2 u, float far_slope) {
  float h0 = heightAt(i, j);
  float step_m = exactStepLength(j, u, 0.5);
  float best = uintBitsToFloat(0xff800000u);
  for (int s = 1; s <= max(NEAR_STEPS, 1); ++s) {
    float t = float(s) * step_m;
    vec2 p = rayPoint(i, j, u, t);
    if (!onGrid(p)) return best;
    if (s <= NEAR_STEPS) best = max(best, (bilinearHeight(clampToGrid(p)) - t * t * INV_TWO_R_EFF - h0) / t);
  }
  return max(best, far_slope);
}

// Whether the ray from texel (i, j) along u stays on the grid through the near steps,
// so that sweptSlope takes the far slope (it can then only rise above it).
bool nearStepsOnGrid(int i, int j, vec2 u) {
  float step_m = exactStepLength(j, u, 0.5);
  for (int s = 1; s <= max(NEAR_STEPS, 1); ++s)
    if (!onGrid(rayPoint(i, j, u, float(s) * step_m))) return false;
  return true;
}
