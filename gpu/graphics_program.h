// A linked vertex + fragment program (RAII) from two embedded shaders plus one generated
// #define block, for the viewer's drawing (view/). Compile and link failures throw with
// the info log, its locations mapped back to <file>:<line> of the embedded files.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "gpu/shader_source.h"

namespace skylit::gpu {

class GraphicsProgram {
 public:
  // shaders/<vertex> and shaders/<fragment>, each with `defines` after its #version
  // line. Needs a current context. Throws std::runtime_error.
  GraphicsProgram(std::string_view vertex, std::string_view fragment, const GlslDefines& defines = {});
  ~GraphicsProgram();
  GraphicsProgram(GraphicsProgram&& other) noexcept;
  GraphicsProgram& operator=(GraphicsProgram&& other) noexcept;
  GraphicsProgram(const GraphicsProgram&) = delete;
  GraphicsProgram& operator=(const GraphicsProgram&) = delete;

  std::uint32_t id() const { return mProgram; }
  void use() const;

  // Uniforms by name (glProgramUniform*). A name the compiler dropped (unused in this
  // variant) is ignored; one that no variant declares is the caller's bug and throws.
  void set(std::string_view name, int value) const;
  void set(std::string_view name, int x, int y) const;  // ivec2
  void set(std::string_view name, float value) const;
  void set(std::string_view name, float x, float y) const;
  void set(std::string_view name, float x, float y, float z) const;
  void set(std::string_view name, float x, float y, float z, float w) const;
  void set_mat4(std::string_view name, const float* column_major) const;
  void set_mat3(std::string_view name, const float* column_major) const;

 private:
  int location(std::string_view name) const;  // -1 when inactive

  std::uint32_t mProgram = 0;
  std::string mName;
  std::string mSourceText;  // both stages' text, to tell a misspelt name from an unused one
};

}  // namespace skylit::gpu
