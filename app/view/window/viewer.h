// The fly-through viewer's loop: a GLFW window whose context the GPU renderer adopts,
// the drawing path of headless `render` (view/scene_view.h) into it, the playback clock
// driving the sun, sky and aircraft, the camera rig fed by keys, mouse or a script, the
// ImGui panel, screenshots at any scale (tiles) and the terrain brush.
#pragma once

#include "app/view/window/viewer_options.h"

namespace skylit::app::view::window {

// Runs until the window closes, a script quits or --frames are done. Throws
// std::invalid_argument / std::runtime_error with one line for what cannot start.
int run_viewer(const ViewerOptions& options);

}  // namespace skylit::app::view::window
