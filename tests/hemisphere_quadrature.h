// Independent test quadrature: the midpoint rule over the upper hemisphere on an
// nt × np grid in (θ from the zenith, φ), not the library's own rules.
#pragma once

#include <glm/vec3.hpp>

#include <cmath>
#include <numbers>

namespace skylit::testing {

// Calls f(direction, solid angle of its cell) for every cell.
template <class F>
void for_each_upper_hemisphere_cell(int nt, int np, const F& f) {
  const double dt = std::numbers::pi / 2 / nt, dp = 2 * std::numbers::pi / np;
  for (int i = 0; i < nt; ++i) {
    const double t = (i + 0.5) * dt;
    for (int j = 0; j < np; ++j) {
      const double p = (j + 0.5) * dp;
      f(glm::dvec3(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)), std::sin(t) * dt * dp);
    }
  }
}

}  // namespace skylit::testing
