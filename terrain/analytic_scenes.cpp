#include "terrain/analytic_scenes.h"

#include <cmath>
#include <stdexcept>

namespace skylit::terrain {
namespace {

// Fills a grid from z(x, y), with (x, y) metric offsets from the centre (y north).
template <class F>
HeightField from_function(int w, int h, double dx, F z) {
  HeightField f(w, h, dx);  // validates size and spacing
  const double ci = 0.5 * (w - 1), cj = 0.5 * (h - 1);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) f.at(i, j) = static_cast<float>(z((i - ci) * dx, (cj - j) * dx, i));
  return f;
}

}  // namespace

HeightField flat_plane(int w, int h, double dx, double height) {
  return from_function(w, h, dx, [&](double, double, int) { return height; });
}

HeightField tilted_plane(int w, int h, double dx, double slope_east, double slope_north, double z0) {
  return from_function(w, h, dx, [&](double x, double y, int) { return z0 + slope_east * x + slope_north * y; });
}

HeightField circular_pit(int w, int h, double dx, double radius, double depth) {
  if (!(radius > 0) || !(depth >= 0)) throw std::invalid_argument("circular_pit: radius must be > 0, depth ≥ 0");
  return from_function(w, h, dx, [&](double x, double y, int) { return std::hypot(x, y) <= radius ? -depth : 0.0; });
}

HeightField long_wall(int w, int h, double dx, double wall_height, double thickness, double axis_x) {
  if (!(thickness > 0)) throw std::invalid_argument("long_wall: thickness must be > 0");
  return from_function(w, h, dx, [&](double, double, int i) {
    return std::abs(i * dx - axis_x) <= 0.5 * thickness ? wall_height : 0.0;
  });
}

HeightField gaussian_hill(int w, int h, double dx, double peak, double sigma) {
  if (!(sigma > 0)) throw std::invalid_argument("gaussian_hill: sigma must be > 0");
  return from_function(w, h, dx, [&](double x, double y, int) {
    return peak * std::exp(-(x * x + y * y) / (2 * sigma * sigma));
  });
}

}  // namespace skylit::terrain
