// Surface normals for products: Horn's 3×3 gradient (as gdaldem), edge pixels
// replicated, metric spacing per row (geographic DEMs), as unit vectors in
// (east, north, up). Row 0 is the northern edge.
#pragma once

#include "terrain/height_field.h"

#include <glm/vec3.hpp>

#include <vector>

namespace skylit::horizon {

// Unit Horn normal of texel (i, j).
glm::dvec3 horn_normal(const terrain::HeightField& field, int i, int j);

// All normals, row-major (width·height).
std::vector<glm::dvec3> horn_normals(const terrain::HeightField& field);

}  // namespace skylit::horizon
