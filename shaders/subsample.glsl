// The coarse grid of horizon sub-sampling (shading::ProductOptions::subsample; GLSL
// twin of horizon::SubsampleAxis, shading/horizon/horizon_subsample.h): positions 0, s,
// 2s, ... and the last index. Needs SUBSAMPLE (> 1).

// Texel index of coarse position c on an axis of `size` texels.
int coarsePosition(int c, int size) { return min(c * SUBSAMPLE, size - 1); }

// Texel t between coarse positions c0 <= c1, weight a on c1 (c0 == c1: t is coarse).
void coarseBracket(int t, int size, out int c0, out int c1, out float a) {
  c0 = t / SUBSAMPLE;
  c1 = c0 * SUBSAMPLE == t ? c0 : c0 + 1;
  int p0 = c0 * SUBSAMPLE;
  a = c1 == c0 ? 0.0 : float(t - p0) / float(coarsePosition(c1, size) - p0);
}
