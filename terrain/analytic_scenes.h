// Analytic test scenes with known geometry, for tests of horizons, sky-view factors and
// shading. All are metric grids (square spacing `dx` m, no CRS), all valid, with
// texel (i, j) centre at metric (x, y) = (i·dx, −j·dx): x east, y north, as in
// height_field.h. "Centre" below means the texel-centre position ((w−1)/2, (h−1)/2),
// i.e. metric (cx, cy) = ((w−1)/2·dx, −(h−1)/2·dx).
#pragma once

#include "terrain/height_field.h"

namespace skylit::terrain {

// z = height everywhere.
HeightField flat_plane(int w, int h, double dx, double height = 0.0);

// z = z0 + slope_east·x + slope_north·y, with x, y the metric offsets from the centre
// (slopes in m/m: slope_east > 0 rises toward the east). Horn normal is exact here.
HeightField tilted_plane(int w, int h, double dx, double slope_east, double slope_north,
                         double z0 = 0.0);

// Flat ground at 0 with a cylindrical pit of `radius` m and `depth` m (floor at −depth)
// around the centre: texels whose centre lies at distance ≤ radius are at −depth.
// From the pit's centre the horizon is atan(depth / radius) in every direction
// (up to the texel discretisation of the rim).
HeightField circular_pit(int w, int h, double dx, double radius, double depth);

// Flat ground at 0 with a straight wall of `wall_height` m, `thickness` m thick, running
// north–south (the full grid height) with its axis at metric x = `axis_x` (east of the
// western edge texel centre, x = i·dx): texels with |x − axis_x| ≤ thickness/2 are raised.
// At ground distance d from the wall face to the east, the horizon toward the west is
// atan(wall_height / d).
HeightField long_wall(int w, int h, double dx, double wall_height, double thickness,
                      double axis_x);

// A Gaussian hill z = peak·exp(−r²/(2σ²)) around the centre; smooth, for gradient tests.
HeightField gaussian_hill(int w, int h, double dx, double peak, double sigma);

}  // namespace skylit::terrain
