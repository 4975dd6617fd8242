// The pieces every atomic raster output shares (raster_writer.h, block_raster_writer.h):
// the checks of a target and a driver, a hidden temporary folder next to the target that
// is removed unless published, and the dataset's georeference and band metadata.
#pragma once

#include <gdal_priv.h>

#include <filesystem>
#include <string>

#include "terrain/raster_writer.h"

namespace skylit::terrain::detail {

[[noreturn]] void fail_write(const std::string& path, const std::string& what, std::string option = {});

class CslList {  // owns a GDAL string list
 public:
  CslList() = default;
  CslList(const CslList&) = delete;
  CslList& operator=(const CslList&) = delete;
  ~CslList() { CSLDestroy(list_); }
  void add(const std::string& s) { list_ = CSLAddString(list_, s.c_str()); }
  char** get() const { return list_; }

 private:
  char** list_ = nullptr;
};

// The output folder exists and is writable, the target is no folder, and it exists only
// when options.overwrite allows.
void check_target(const std::string& path, const RasterWriteOptions& options);
// Size, bands, descriptions, creation options' syntax and a Byte nodata value.
void check_layout(const std::string& path, int width, int height, int bands, GDALDataType type,
                  const RasterWriteOptions& options);
// The driver of options.format, checked to write rasters of `type`; creation options
// validated against it.
GDALDriver& writable_driver(const std::string& path, GDALDataType type, const RasterWriteOptions& options,
                            const CslList& creation_options);
// Whether the driver writes by Create (else the output is a CreateCopy of a staged raster).
bool creates_directly(GDALDriver& driver, const std::string& format);

// A hidden folder beside `target` for building it; removed with its contents unless
// publish() moved them into place.
class StagingDir {
 public:
  explicit StagingDir(const std::string& target);  // throws RasterWriteError
  StagingDir(const StagingDir&) = delete;
  StagingDir& operator=(const StagingDir&) = delete;
  ~StagingDir();
  // Where the target is built (the target itself for a /vsi path, which is not staged).
  std::string file(const std::string& name) const;
  std::string target_file() const;
  // Moves the built target and its sidecars (.aux.xml) next to the target, the target
  // last, so no reader sees it without its sidecars. Nothing for a /vsi path.
  void publish();

 private:
  std::filesystem::path target_, path_;
};

// Geotransform, CRS, every band's nodata, description and colour interpretation.
void describe_dataset(GDALDataset& ds, const std::string& path, const GeoReference& georef, int bands,
                      GDALDataType type, const RasterWriteOptions& options);

}  // namespace skylit::terrain::detail
