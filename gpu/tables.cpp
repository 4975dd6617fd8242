#include "gpu/tables.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace skylit::gpu {
namespace {

void check_shape(std::size_t count, int rows, int cols) {
  if (rows < 0 || cols < 0 || count != static_cast<std::size_t>(rows) * cols)
    throw std::invalid_argument("table of " + std::to_string(count) + " values is not " +
                                std::to_string(rows) + " × " + std::to_string(cols));
}

}  // namespace

GpuTable upload_storage_table(std::span<const float> row_major, int rows, int cols) {
  check_shape(row_major.size(), rows, cols);
  return {Buffer::from(row_major), rows, cols};
}

GpuTable upload_storage_table(std::span<const double> row_major, int rows, int cols) {
  const std::vector<float> f32(row_major.begin(), row_major.end());
  return upload_storage_table(std::span<const float>(f32), rows, cols);
}

GpuTable upload_uniform_table(std::span<const double> row_major, int rows, int cols) {
  check_shape(row_major.size(), rows, cols);
  std::vector<float> padded((row_major.size() + 3) / 4 * 4, 0.0f);
  std::copy(row_major.begin(), row_major.end(), padded.begin());
  return {Buffer::from(std::span<const float>(padded)), rows, cols};
}

void define_table_shape(GlslDefines& defines, std::string_view name, const GpuTable& table) {
  const std::string n(name);
  defines.set(n + "_ROWS", table.rows)
      .set(n + "_COLS", table.cols)
      .set(n + "_SIZE", table.rows * table.cols);
}

}  // namespace skylit::gpu
