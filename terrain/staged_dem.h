// A DEM staged for GDAL's warper, the source of every web-map tile window: Float32
// metres, north up, NaN at voids. It is held in memory (GDAL's MEM driver) up to a byte
// limit; above it, it is written a strip of rows at a time to a temporary tiled GeoTIFF
// and read back through GDAL's block cache, so that a tile run's peak memory does not
// grow with the DEM.
//
// Policy decisions (tests rely on them):
//  * Values: read_dem's heights (the same conversion, masks and checks) as Float32, NaN
//    where valid == 0, the same bits in memory and on disk: tiles do not depend on where
//    the copy lives.
//  * The file: <directory>/skylit-staged-<pid>-<n>.tif, uncompressed, in 256 × 256
//    blocks, BigTIFF when needed. It is deleted as soon as it is reopened for reading
//    (the open handle keeps its data), so no later exit, error or signal leaves it
//    behind; a run killed while writing it does.
//  * The outline: read_dem's field without pixels (size, georef, spacing, nodata).
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "terrain/dem_reader.h"
#include "terrain/height_field.h"

class GDALDataset;

namespace skylit::terrain {

struct StagingOptions {
  std::size_t memory_limit_bytes = std::size_t{512} << 20;  // larger copies go to disk
  std::filesystem::path directory;  // of the temporary file; empty: the system's temp folder
  // Pixels read per strip: 256 rows of a 16384-wide DEM, some 60 MB in flight.
  std::size_t strip_pixels = std::size_t{1} << 22;
};

class StagedDem {
 public:
  // The field's heights in memory (tests, and callers that hold the field anyway).
  static StagedDem from_field(const HeightField& field);
  // The DEM read a strip at a time (read_dem_in_strips); warnings are appended, and
  // `progress` gets the fraction of rows read after each strip. Throws DemError as
  // read_dem does, and when the copy cannot be written.
  static StagedDem read(const std::vector<std::string>& paths, const DemReadOptions& read,
                        const StagingOptions& staging, std::vector<std::string>& warnings,
                        const std::function<void(double)>& progress = {});

  ~StagedDem();
  StagedDem(StagedDem&&) noexcept;
  StagedDem& operator=(StagedDem&&) noexcept;

  const HeightField& outline() const;  // no heights or mask: outline().heights is empty
  std::size_t valid_count() const;     // pixels with a height
  bool has_voids() const { return valid_count() < static_cast<std::size_t>(outline().width) * outline().height; }
  // The height at (width/2, height/2), or the lowest height when that pixel is a void.
  float centre_height() const;
  bool on_disk() const;
  GDALDataset& dataset() const;  // band 1: the heights; not thread-safe

 private:
  struct Impl;
  explicit StagedDem(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace skylit::terrain
