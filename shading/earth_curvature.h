// Earth-curvature drop of distant terrain as seen along a horizon ray: a point at
// ground distance d sits d²/(2·R_eff) lower than on a flat Earth, where refraction
// bends sight lines with coefficient k: R_eff = R/(1 − k) (k = 0.13, R = 6 371 km,
// the usual geodetic/radio-horizon values).
#pragma once

namespace skylit::shading {

struct EarthCurvature {
  bool enabled = true;
  double radius_m = 6371000.0;
  double refraction_k = 0.13;

  double effective_radius() const { return radius_m / (1.0 - refraction_k); }
  // Height drop (m) at ground distance d (m); 0 when disabled.
  double drop(double d) const { return enabled ? d * d / (2.0 * effective_radius()) : 0.0; }
};

}  // namespace skylit::shading
