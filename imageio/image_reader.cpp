#include "imageio/image_reader.h"

#include "imageio/oiio_api.h"

#include <dlfcn.h>

#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace skylit::imageio {
namespace {

struct Module {
  SkylitOiioRead* read = nullptr;
  SkylitOiioFree* release = nullptr;
  std::string error;  // why it could not be loaded
};

// Next to the running executable (an installed or copied binary), else the build tree.
std::vector<std::filesystem::path> module_candidates() {
  std::vector<std::filesystem::path> out;
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) out.push_back(exe.parent_path() / SKYLIT_OIIO_READER_NAME);
  out.push_back(std::filesystem::path(SKYLIT_OIIO_READER_BUILD_DIR) / SKYLIT_OIIO_READER_NAME);
  return out;
}

Module load_module() {
  Module m;
  std::string tried;
  for (const auto& path : module_candidates()) {
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);  // kept for the process
    if (!handle) {
      tried += (tried.empty() ? "" : "; ") + std::string(dlerror());
      continue;
    }
    m.read = reinterpret_cast<SkylitOiioRead*>(dlsym(handle, kSkylitOiioReadSymbol));
    m.release = reinterpret_cast<SkylitOiioFree*>(dlsym(handle, kSkylitOiioFreeSymbol));
    if (m.read && m.release) return m;
    tried += (tried.empty() ? "" : "; ") + path.string() + " lacks the reader's symbols";
    m = {};
  }
  m.error = "the image reader module " + std::string(SKYLIT_OIIO_READER_NAME) + " (OpenImageIO) could not be loaded: " + tried;
  return m;
}

const Module& module() {
  static const Module m = load_module();  // once per process, thread-safe
  return m;
}

}  // namespace

FloatImage read_float_image(const std::string& path, int max_channels) {
  if (max_channels < 1) throw std::invalid_argument("read_float_image: max_channels must be ≥ 1");
  const Module& m = module();
  if (!m.read) throw std::runtime_error("cannot read '" + path + "': " + m.error);
  FloatImage image;
  float* pixels = nullptr;
  char error[512] = {};
  if (m.read(path.c_str(), max_channels, &image.width, &image.height, &image.channels, &pixels, error, sizeof error) != 0)
    throw std::runtime_error("cannot read '" + path + "': " + error);
  const std::size_t count = static_cast<std::size_t>(image.width) * image.height * image.channels;
  image.pixels.assign(pixels, pixels + count);
  m.release(pixels);
  return image;
}

}  // namespace skylit::imageio
