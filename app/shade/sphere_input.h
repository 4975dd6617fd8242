// `--spheres FILE.csv`: static sphere blockers given in the DEM's CRS (header
// x,y,z,radius; x, y in the CRS's units, z and radius in metres, z in the DEM's vertical
// datum), placed in the renderer's field frame (shading/renderer.h FrameInputs).
#pragma once

#include "shading/blockers/sphere_blocker.h"
#include "terrain/height_field.h"

#include <glm/vec2.hpp>

#include <string>
#include <vector>

namespace skylit::app::shade {

// Most spheres a file may hold (the binning and the truth are linear in them).
inline constexpr std::size_t kMaxSpheres = 1'000'000;

// Throws std::invalid_argument with one line ("FILE:LINE: …") for a missing or bad
// header, a line that is not four finite numbers, a radius ≤ 0, no spheres, or more
// than kMaxSpheres.
std::vector<blockers::Sphere> read_spheres_csv(const std::string& path);

// The fractional texel (centres at integers) of CRS coordinates (x, y), through the DEM's
// geotransform; a DEM without one is in texels.
glm::dvec2 texel_of(const terrain::HeightField& field, double x, double y);

// CRS coordinates → field frame, through texel_of (texel (i, j) at (i·dx, −j·dy)).
std::vector<blockers::Sphere> to_field_frame(const terrain::HeightField& field,
                                                      const std::vector<blockers::Sphere>& crs);

}  // namespace skylit::app::shade
