#include "gpu/embedded_shaders.h"

#include <stdexcept>
#include <string>

namespace skylit::gpu {

std::span<const EmbeddedShader> embedded_shaders() {
  return {detail::kEmbeddedShaders, detail::kEmbeddedShaderCount};
}

std::string_view embedded_shader(std::string_view name) {
  for (const EmbeddedShader& s : embedded_shaders())
    if (!name.empty() && name == s.name) return s.text;
  throw std::out_of_range("no embedded shader named '" + std::string(name) +
                          "' (shaders/ is embedded at build time; re-run the build?)");
}

}  // namespace skylit::gpu
