// A raster written block by block, for outputs larger than memory: the file is built in
// a hidden folder next to the target (raster_output.h) and appears only at finish(), as
// write_raster's do. Formats GDAL creates directly (GTiff, …) are written in place;
// copy-only ones (COG, PNG, …) are staged as a tiled GeoTIFF on disk and copied at
// finish() (COG builds its overviews then), so memory stays bounded by GDAL's cache.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "terrain/raster_writer.h"

namespace skylit::terrain {

class BlockRasterWriter {
 public:
  enum class Sample { Float32, Byte };
  // Checks as write_raster does (RasterWriteError); options.layout must be BandSequential.
  BlockRasterWriter(const std::string& path, const GeoReference& georef, int width, int height, int bands,
                    Sample sample, const RasterWriteOptions& options = {});
  ~BlockRasterWriter();  // without finish(): nothing is left behind
  BlockRasterWriter(const BlockRasterWriter&) = delete;
  BlockRasterWriter& operator=(const BlockRasterWriter&) = delete;

  // Band-sequential samples of `rect` (rect.width·rect.height·bands values).
  void write(const PixelRect& rect, std::span<const float> data);
  void write(const PixelRect& rect, std::span<const std::uint8_t> data);
  // Copies a staged raster into its format and moves the file into place.
  // progress (options.progress) covers the copy.
  void finish();

 private:
  void write_any(const PixelRect& rect, const void* data, std::size_t values, Sample sample);
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace skylit::terrain
