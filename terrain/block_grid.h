// A raster cut into blocks for processing larger than one field (DESIGN.md "Scale"): each
// block's core is written, its read window is the core grown by a halo and clipped to
// the raster, so every core texel sees at least `halo` texels of terrain in every
// direction the raster has them.
#pragma once

#include <vector>

#include "terrain/height_field.h"

namespace skylit::terrain {

struct RasterBlock {
  PixelRect core;  // the texels this block writes
  PixelRect read;  // core ± halo, clipped to the raster
};

// Row-major blocks of `block_size` × `block_size` texels from (0, 0); the last column and
// row are narrower where the raster is not a multiple of it. Throws std::invalid_argument
// for a raster or block size under 1 or a negative halo.
std::vector<RasterBlock> block_grid(int width, int height, int block_size, int halo);

}  // namespace skylit::terrain
