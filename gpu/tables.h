// Handing C++-computed tables (wedge operators, NLP/ZH coefficients, …) to shaders:
// the values go to a buffer as float32, and their shape goes into the shader's
// generated #define block, so neither values nor sizes are typed in GLSL.
#pragma once

#include <span>
#include <string_view>

#include "gpu/buffers.h"
#include "gpu/shader_source.h"

namespace skylit::gpu {

// A row-major rows × cols float32 matrix in a buffer.
struct GpuTable {
  Buffer buffer;
  int rows = 0;
  int cols = 0;
};

// For an SSBO: tightly packed (std430 `float NAME[]`, element (r, c) at r·cols + c).
// Throws std::invalid_argument if values.size() != rows·cols.
GpuTable upload_storage_table(std::span<const double> row_major, int rows, int cols);
GpuTable upload_storage_table(std::span<const float> row_major, int rows, int cols);

// For a UBO (std140 pads float arrays to 16-byte strides): packed as `vec4 NAME[N]`,
// element k at NAME[k / 4][k % 4], zero-padded to a multiple of 4 values.
GpuTable upload_uniform_table(std::span<const double> row_major, int rows, int cols);

// Defines NAME_ROWS, NAME_COLS and NAME_SIZE (rows·cols) for the shader.
void define_table_shape(GlslDefines& defines, std::string_view name, const GpuTable& table);

}  // namespace skylit::gpu
