// A height field at half the resolution, for a DEM too large for one GPU frame (the
// viewer shows a coarser level rather than failing): each texel the mean of a 2×2 block.
#pragma once

#include "terrain/height_field.h"

namespace skylit::terrain {

// floor(width/2) × floor(height/2) texels (a last odd row or column is dropped), each the
// mean of the valid heights of its 2×2 block (valid when any is; else the mean of the
// filled heights, nodata). Spacing doubles; the geotransform keeps its corner and doubles
// its pixel size, so texel (I, J) covers the source's (2I..2I+1, 2J..2J+1). Throws
// std::invalid_argument for a side under 2.
HeightField coarsen_by_two(const HeightField& field);

}  // namespace skylit::terrain
