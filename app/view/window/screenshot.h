// Screenshots at any scale: the frame drawn in tiles of the window's size into an
// off-screen target (each tile's projection a window of the whole; the renderer's
// shading computed once), stitched and written as PNG. The panel is not in them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "view/scene_view.h"

namespace skylit::app::view::window {

struct RgbImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // rows top first
};

// width·scale × height·scale pixels of `frame` (whose camera is for width × height).
RgbImage render_tiled(skylit::view::SceneView& scene, const skylit::view::ViewFrame& frame, int width, int height,
                      int scale);
// Throws std::invalid_argument (one line) for an existing file without overwrite or a
// missing folder.
void check_screenshot_path(const std::string& path, bool overwrite);
void write_screenshot(const std::string& path, const RgbImage& image, bool overwrite);
// skylit-YYYYmmdd-HHMMSS.png in the working folder (with -2, -3, … if taken).
std::string default_screenshot_name();

}  // namespace skylit::app::view::window
