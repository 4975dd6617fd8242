// Float images from files any format OpenImageIO reads (EXR, Radiance HDR, TIFF, PNG,
// ...), through a module loaded on the first call (imageio/CMakeLists.txt: why).
#pragma once

#include <string>
#include <vector>

namespace skylit::imageio {

struct FloatImage {
  int width = 0, height = 0, channels = 0;
  std::vector<float> pixels;  // row-major, top row first, `channels` interleaved
};

// The first `max_channels` channels of `path` (fewer if it has fewer). Throws
// std::runtime_error naming the file if it cannot be read, or naming the module and
// where it was looked for if that cannot be loaded.
FloatImage read_float_image(const std::string& path, int max_channels);

}  // namespace skylit::imageio
