// Writing result rasters (float32 products, 8-bit images) with the DEM's
// georeferencing through GDAL. Writes are atomic: the raster (and any sidecar such as
// .aux.xml) is built in a hidden temporary folder next to the target and renamed into
// place only when complete; on any failure the temporaries are deleted, so no partial
// output is ever left behind.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "terrain/height_field.h"

namespace skylit::terrain {

// Every writer failure; what() is one line naming the file and the problem. option():
// the RasterWriteOptions member that would fix it ("overwrite"), or empty; library
// messages name no command-line flag, a front end adds its own for option().
class RasterWriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
  RasterWriteError(const std::string& what, std::string option)
      : std::runtime_error(what), option_(std::move(option)) {}
  const std::string& option() const { return option_; }

 private:
  std::string option_;
};

enum class SampleLayout {
  BandSequential,   // band b occupies data[b·w·h, (b+1)·w·h), each band row-major
  PixelInterleaved  // data[(j·w + i)·bands + b] (RGBRGB…)
};

struct RasterWriteOptions {
  std::string format = "GTiff";                 // GDAL driver: GTiff, COG, PNG, … (-of)
  std::vector<std::string> creation_options;    // "NAME=VALUE" (-co), passed to the driver
  std::optional<double> nodata;                 // written as every band's nodata value
  SampleLayout layout = SampleLayout::BandSequential;
  std::vector<std::string> band_descriptions;   // optional, one per band
  bool overwrite = true;                        // false: error if the target exists
  // Called with the completed fraction in [0, 1]; return false to cancel (throws).
  std::function<bool(double)> progress;
};

// Float32 raster with `bands` bands (data.size() == w·h·bands). Georeference from
// `georef` (geotransform + CRS; an empty CRS writes none).
void write_raster(const std::string& path, const GeoReference& georef, int width, int height,
                  int bands, std::span<const float> data, const RasterWriteOptions& options = {});

// 8-bit raster: 1 band (gray), 3 (RGB) or 4 (RGBA); colour interpretation set to match.
void write_raster(const std::string& path, const GeoReference& georef, int width, int height,
                  int bands, std::span<const std::uint8_t> data,
                  const RasterWriteOptions& options = {});

// Convenience: the height field itself (heights, nodata where !valid when
// field.nodata is set, else −32768 is used and recorded as nodata).
void write_height_field(const std::string& path, const HeightField& field,
                        const RasterWriteOptions& options = {});

}  // namespace skylit::terrain
