// The C interface between skylit_imageio and its OpenImageIO module (both sides
// include this file, so the signatures cannot drift). C linkage: no C++ exception or
// type crosses the dlopen() boundary.
#pragma once

#include <cstddef>

extern "C" {
// Reads the first `max_channels` channels (fewer if the image has fewer) of `path` as
// float, row-major, top row first, into a buffer that skylit_oiio_free releases.
// Returns 0 on success; otherwise writes a message (NUL-terminated, truncated to
// error_size) and returns non-zero.
using SkylitOiioRead = int(const char* path, int max_channels, int* width, int* height, int* channels,
                           float** pixels, char* error, std::size_t error_size);
using SkylitOiioFree = void(float* pixels);
}

// The symbol names the loader looks up.
inline constexpr const char* kSkylitOiioReadSymbol = "skylit_oiio_read";
inline constexpr const char* kSkylitOiioFreeSymbol = "skylit_oiio_free";
