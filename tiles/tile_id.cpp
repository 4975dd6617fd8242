#include "tiles/tile_id.h"

namespace skylit::tiles {

std::string to_string(const TileId& t) {
  return std::to_string(t.z) + "/" + std::to_string(t.x) + "/" + std::to_string(t.y);
}

}  // namespace skylit::tiles
