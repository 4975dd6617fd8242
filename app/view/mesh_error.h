// `--mesh-error PX` of `render` and the window: the terrain mesh's geometric error on
// screen (view/terrain_lod.h), checked in one line.
#pragma once

#include <stdexcept>

#include "view/terrain_lod.h"

namespace skylit::app::view {

inline void check_mesh_error(double px) {
  if (!(px >= skylit::view::kMinMeshErrorPx && px <= skylit::view::kMaxMeshErrorPx))
    throw std::invalid_argument("--mesh-error must be 0.5 to 16 pixels");
}

}  // namespace skylit::app::view
