// Turning an embedded shader into compilable GLSL: C++ values become a generated
// #define block ("no constant typed twice"), `#include "x.glsl"` lines are resolved
// from the embedded table (core GL has no #include), and a line map turns compiler
// messages about the assembled text back into file:line of the original files.
// (No `#line` markers: Mesa ignores their source-string number, so the map is the
// one method that works on every driver.)
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace skylit::gpu {

// An ordered set of `#define NAME value` lines built from C++ values. Floating-point
// values are written with 9 significant digits, which round-trips float32 exactly.
class GlslDefines {
 public:
  GlslDefines& set(std::string_view name, int value);
  GlslDefines& set(std::string_view name, double value);
  // Throws std::invalid_argument for a bad identifier or a name set twice.
  GlslDefines& set_literal(std::string_view name, std::string_view glsl_expression);

  std::string text() const;  // one "#define NAME value" line per entry, in order
  bool empty() const { return mEntries.empty(); }

 private:
  std::vector<std::pair<std::string, std::string>> mEntries;
};

// Float literal for GLSL (always with '.' or exponent): the value rounded to float32 once,
// in C++, and written with the 9 significant digits that bring exactly that float back,
// so the shader's constant equals static_cast<float>(value) (printing the double would
// round twice: to 9 digits, then the compiler to float, which can land one ulp off).
std::string glsl_float_literal(double value);
// GLSL array constructor of those literals: "float[n](a, b, …)".
std::string glsl_float_array_literal(std::span<const double> values);

struct AssembledShader {
  std::string text;  // ready for glShaderSource
  // Every file that went in: 0 = the generated #define block, 1 = the main file, then
  // includes in order of first use.
  std::vector<std::string> source_names;
  // Origin of each line of `text` (entry n = line n + 1): source index, line in it.
  struct Origin {
    int source;
    int line;
  };
  std::vector<Origin> line_origins;

  // Rewrites the driver's "0:<line>" (Mesa, AMD) and "0(<line>)" (NVIDIA) locations
  // in a compiler info log as "<file>:<line>" of the original file.
  std::string map_log(std::string_view log) const;
};

// `text` (named `name` in messages) must begin with its `#version` line; the defines go
// right after it. Each embedded file is included at most once. Throws
// std::runtime_error for a missing #version or an unknown include.
AssembledShader assemble_shader_text(std::string_view name, std::string_view text,
                                     const GlslDefines& defines);

// The same for the embedded file shaders/<name>.
AssembledShader assemble_shader(std::string_view name, const GlslDefines& defines);

}  // namespace skylit::gpu
