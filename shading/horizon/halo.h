// How much terrain beyond a region its horizons read: a region processed apart from the
// rest of its DEM (a map tile's window, a block of a large DEM) is read with a halo this
// wide, so that its texels see what they would see in the whole DEM (DESIGN.md "Scale").
#pragma once

#include <cmath>

namespace skylit::horizon {

// The horizon search distance (ground metres) of runs that must bound it (tiles, blocks):
// 5 km holds the ridges that shade most valleys; docs/tiles.md measures what it costs
// against a 4× larger halo.
inline constexpr double kDefaultBoundedDistanceM = 5000.0;
// Texels past the search distance that the march's pyramid and B-spline kernels read.
inline constexpr int kKernelMarginTexels = 8;

// The halo (texels) that holds a search of `max_distance_m` on texels of at least
// `smallest_spacing_m` on a side.
inline double halo_texels(double max_distance_m, double smallest_spacing_m) {
  return std::ceil(max_distance_m / smallest_spacing_m) + kKernelMarginTexels;
}

}  // namespace skylit::horizon
