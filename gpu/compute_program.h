// A linked GLSL compute program (RAII), compiled from an embedded shader plus a
// generated #define block. Compile and link failures throw with the full info log.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "gpu/shader_source.h"

namespace skylit::gpu {

class ComputeProgram {
 public:
  // shaders/<name> with `defines` after its #version line. Needs a current context.
  // Throws std::runtime_error("compiling <name> failed:\n<info log>"), the log's
  // locations mapped back to <file>:<line> of the embedded files.
  static ComputeProgram from_embedded(std::string_view name, const GlslDefines& defines = {});

  // Already assembled source (assemble_shader_text lets tests compile inline GLSL).
  explicit ComputeProgram(const AssembledShader& source);
  ~ComputeProgram();
  ComputeProgram(ComputeProgram&& other) noexcept;
  ComputeProgram& operator=(ComputeProgram&& other) noexcept;
  ComputeProgram(const ComputeProgram&) = delete;
  ComputeProgram& operator=(const ComputeProgram&) = delete;

  std::uint32_t id() const { return mProgram; }
  const std::string& name() const { return mName; }
  // The shader's layout(local_size_x, _y, _z), queried from the linked program.
  const std::array<int, 3>& local_size() const { return mLocalSize; }

  // Whether `name` is an active uniform (the compiler drops unused ones).
  bool has_uniform(std::string_view name) const;

  // Uniforms by name (glProgramUniform*, no bind needed). Throws if `name` is not an
  // active uniform, so a misspelt uniform is not silently ignored; check has_uniform()
  // first where a variant of the shader may not use it.
  void set_uniform(std::string_view name, int value) const;
  void set_uniform(std::string_view name, unsigned value) const;
  void set_uniform(std::string_view name, float value) const;
  void set_uniform(std::string_view name, double value) const;  // a GLSL double
  void set_uniform(std::string_view name, float x, float y, float z) const;  // vec3
  void set_uniform(std::string_view name, int x, int y) const;                // ivec2

  // Binds the program and dispatches enough work groups to cover nx × ny × nz
  // invocations (the shader must skip the excess). Then a full memory barrier, so the
  // next dispatch or read-back sees the results.
  void dispatch_covering(int nx, int ny = 1, int nz = 1) const;

 private:
  int uniform_location(std::string_view name) const;

  std::uint32_t mProgram = 0;
  std::string mName;
  std::array<int, 3> mLocalSize{1, 1, 1};
};

}  // namespace skylit::gpu
