// The OpenImageIO module of skylit_imageio (imageio/CMakeLists.txt says why it is one).
#include "imageio/oiio_api.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstring>
#include <exception>
#include <string>
#include <type_traits>

namespace {

int fail(const std::string& message, char* error, std::size_t error_size) {
  if (error && error_size > 0) {
    std::strncpy(error, message.c_str(), error_size - 1);
    error[error_size - 1] = '\0';
  }
  return 1;
}

}  // namespace

extern "C" __attribute__((visibility("default"))) int skylit_oiio_read(const char* path, int max_channels, int* width,
                                                                      int* height, int* channels, float** pixels,
                                                                      char* error, std::size_t error_size) {
  try {
    auto in = OIIO::ImageInput::open(path);
    if (!in) return fail(OIIO::geterror(), error, error_size);
    const OIIO::ImageSpec spec = in->spec();
    const int n = std::min(spec.nchannels, max_channels);
    if (spec.width < 1 || spec.height < 1 || n < 1) return fail("the image has no pixels", error, error_size);
    const std::size_t count = static_cast<std::size_t>(spec.width) * spec.height * n;
    auto* out = new float[count];
    if (!in->read_image(0, 0, 0, n, OIIO::TypeDesc::FLOAT, out)) {
      delete[] out;
      return fail("cannot read its pixels: " + in->geterror(), error, error_size);
    }
    in->close();
    *width = spec.width, *height = spec.height, *channels = n, *pixels = out;
    return 0;
  } catch (const std::exception& e) {
    return fail(e.what(), error, error_size);
  }
}

extern "C" __attribute__((visibility("default"))) void skylit_oiio_free(float* pixels) { delete[] pixels; }

// The declarations of oiio_api.h and these definitions must agree.
static_assert(std::is_same_v<decltype(skylit_oiio_read), SkylitOiioRead>);
static_assert(std::is_same_v<decltype(skylit_oiio_free), SkylitOiioFree>);
