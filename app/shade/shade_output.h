// Where and how `shade` writes its product: format from -of or the extension,
// checks made before any computation (existing file, unwritable folder, a
// format that cannot hold the product), and the conversion of float bands
// to the written sample type with nodata.
#pragma once

#include "shading/products.h"
#include "terrain/height_field.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace skylit::app::shade {

struct OutputSpec {
  std::string path;
  std::string format;  // GDAL driver name
  std::vector<std::string> creation_options;
  bool eight_bit = false;  // shaded relief: Byte with nodata 0; others Float32 with nodata −9999
  bool overwrite = false;
};

inline constexpr double kFloatNodata = -9999.0;
inline constexpr double kByteNodata = 0.0;

// Throws std::invalid_argument with a one-line message when the output cannot work.
OutputSpec resolve_output(const std::string& path, const std::string& format, shading::Product product,
                          const std::vector<std::string>& creation_options, bool overwrite);

void write_product(const OutputSpec& spec, const terrain::HeightField& field, const shading::ProductBands& bands);

// The written samples of float bands: 8-bit codes 1…255 with kByteNodata where not
// finite, or Float32 with kFloatNodata there.
std::vector<std::uint8_t> byte_samples(std::span<const float> values);
std::vector<float> float_samples(std::span<const float> values);

}  // namespace skylit::app::shade
