// Numbered output names: one %d-style conversion in a path stands for the frame number
// (frames/shadow_%04d.png; frame numbers from 0, as ffmpeg reads them). Shared by
// shade's time series and render's PNG frames.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>

namespace skylit::app {

// The one %d conversion of `path` ("%d", "%04d", "%4d"), as {position, length}; nullopt
// without one. Throws std::invalid_argument for any other '%' (write "%%" for a percent
// sign) or a second %d.
std::optional<std::pair<std::size_t, std::size_t>> frame_pattern(const std::string& path);
// `path` with its %d conversion replaced by `frame`.
std::string frame_path(const std::string& path, int frame);

}  // namespace skylit::app
