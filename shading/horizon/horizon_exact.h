// Exact horizon (ground truth, `--exact`; DESIGN.md "Ground truth", math-notes §8):
// from the pixel centre's own height, march every half texel (along the ray's
// dominant grid axis) with bilinear heights until the DEM edge or the maximum
// distance, Earth-curvature drop included, and take the plain max of the elevation
// angles. No pyramid, no smoothing: slow and exact up to the half-texel step.
#pragma once

#include "shading/horizon/azimuth.h"
#include "shading/horizon/earth_curvature.h"
#include "shading/horizon/horizon_ray.h"
#include "terrain/height_field.h"

namespace skylit::horizon {

struct ExactMarch {
  double step_texels = 0.5;    // step length in texels of the ray's dominant axis
  double max_distance_m = 0.0; // 0 = the DEM extent
  EarthCurvature curvature;
};

// Metric step (m) of the exact march along u: step_texels of the dominant axis.
double exact_step_length(const terrain::HeightField& field, int row, Heading u, double step_texels);

// Largest elevation angle (radians) from texel (i, j) along u; −∞ if the first step
// already leaves the grid.
double exact_max_elevation(const terrain::HeightField& field, int i, int j, Heading u, const ExactMarch& options);
// Offset marching (seed 000 §4.1): the same from a point at height h0 (m) above level-0
// texel coordinates `origin` on the grid; the step is that of the origin's nearest row.
double exact_max_elevation_from(const terrain::HeightField& field, GridPoint origin, double h0, Heading u,
                                const ExactMarch& options);

}  // namespace skylit::horizon
