// Earth-curvature drop of distant terrain as seen along a horizon ray: a point at
// ground distance d sits d²/(2·R_eff) lower than on a flat Earth, where refraction
// bends sight lines with coefficient k: R_eff = R/(1 − k) (k = 0.13, R = 6 371 km,
// the usual geodetic/radio-horizon values).
#pragma once

namespace skylit::horizon {

struct EarthCurvature {
  bool enabled = true;
  double radius_m = 6371000.0;
  double refraction_k = 0.13;

  double effective_radius() const { return radius_m / (1.0 - refraction_k); }
  // drop(d) = d² times this: 1/(2·R_eff) (1/m), 0 when disabled; the GPU kernels get it.
  double drop_per_square_metre() const { return enabled ? 1.0 / (2.0 * effective_radius()) : 0.0; }
  // Height drop (m) at ground distance d (m); 0 when disabled.
  double drop(double d) const { return d * d * drop_per_square_metre(); }
};

}  // namespace skylit::horizon
