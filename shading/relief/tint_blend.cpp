#include "shading/relief/tint_blend.h"

#include <cmath>

namespace skylit::relief {

double soft_light(double cb, double cs) {
  if (cs <= 0.5) return cb - (1.0 - 2.0 * cs) * cb * (1.0 - cb);
  const double d = cb <= 0.25 ? ((16.0 * cb - 12.0) * cb + 4.0) * cb : std::sqrt(cb);
  return cb + (2.0 * cs - 1.0) * (d - cb);
}

double multiply_mix(double colour, double relief, double weight) { return colour * (1.0 - weight + weight * relief); }

double soft_light_mix(double colour, double relief, double weight) {
  return weight * soft_light(colour, relief) + (1.0 - weight) * colour;
}

}  // namespace skylit::relief
