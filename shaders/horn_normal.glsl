// Horn's 3x3 gradient, edge texels replicated, unit (east, north, up): twin of
// horizon::horn_normal. Differences are taken against the centre height, so float
// keeps the small slopes of high terrain.
//
// Needs horizon_ray.glsl (included first: heightAt, rowDx, grid_dy).

float hornHeight(int i, int j, float h0) {
  return heightAt(clamp(i, 0, grid_width - 1), clamp(j, 0, grid_height - 1)) - h0;
}

vec3 hornNormal(int i, int j) {
  float h0 = heightAt(i, j);
  float nw = hornHeight(i - 1, j - 1, h0), n = hornHeight(i, j - 1, h0), ne = hornHeight(i + 1, j - 1, h0);
  float w = hornHeight(i - 1, j, h0), e = hornHeight(i + 1, j, h0);
  float sw = hornHeight(i - 1, j + 1, h0), s = hornHeight(i, j + 1, h0), se = hornHeight(i + 1, j + 1, h0);
  float dzdx = ((ne + 2.0 * e + se) - (nw + 2.0 * w + sw)) / (8.0 * rowDx(j));
  float dzdy = ((nw + 2.0 * n + ne) - (sw + 2.0 * s + se)) / (8.0 * grid_dy);
  return normalize(vec3(-dzdx, -dzdy, 1.0));
}
