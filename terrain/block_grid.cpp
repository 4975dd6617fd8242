#include "terrain/block_grid.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace skylit::terrain {

std::vector<RasterBlock> block_grid(int width, int height, int block_size, int halo) {
  if (width < 1 || height < 1) throw std::invalid_argument("block_grid: empty raster");
  if (block_size < 1) throw std::invalid_argument("block_grid: block size " + std::to_string(block_size) + " under 1");
  if (halo < 0) throw std::invalid_argument("block_grid: negative halo");
  std::vector<RasterBlock> blocks;
  for (int y0 = 0; y0 < height; y0 += block_size)
    for (int x0 = 0; x0 < width; x0 += block_size) {
      RasterBlock b;
      b.core = {x0, y0, std::min(block_size, width - x0), std::min(block_size, height - y0)};
      const int rx0 = std::max(0, x0 - halo), ry0 = std::max(0, y0 - halo);
      const int rx1 = std::min(width, b.core.x1() + halo), ry1 = std::min(height, b.core.y1() + halo);
      b.read = {rx0, ry0, rx1 - rx0, ry1 - ry0};
      blocks.push_back(b);
    }
  return blocks;
}

}  // namespace skylit::terrain
