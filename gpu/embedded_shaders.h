// The GLSL sources compiled into the binary at build time (cmake/embed_text_files.cmake
// turns shaders/*.comp and shaders/*.glsl into a generated C++ source).
#pragma once

#include <cstddef>
#include <span>
#include <string_view>

namespace skylit::gpu {

struct EmbeddedShader {
  const char* name;  // file name inside shaders/, e.g. "horizon_exact.comp"
  const char* text;  // the file's contents, verbatim
};

// Every embedded shader, sorted by name.
std::span<const EmbeddedShader> embedded_shaders();

// The text of shaders/<name>; throws std::out_of_range naming the file if absent.
std::string_view embedded_shader(std::string_view name);

namespace detail {
extern const EmbeddedShader kEmbeddedShaders[];
extern const std::size_t kEmbeddedShaderCount;
}  // namespace detail

}  // namespace skylit::gpu
