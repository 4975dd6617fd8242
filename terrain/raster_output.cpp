#include "terrain/raster_output.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <vector>

#include "terrain/gdal_util.h"

namespace skylit::terrain::detail {
namespace {

namespace fs = std::filesystem;

std::string lower_name(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool is_virtual(const std::string& path) { return path.rfind("/vsi", 0) == 0; }

}  // namespace

void fail_write(const std::string& path, const std::string& what, std::string option) {
  throw RasterWriteError("cannot write '" + path + "': " + what, std::move(option));
}

void check_target(const std::string& path, const RasterWriteOptions& options) {
  if (path.empty()) throw RasterWriteError("cannot write a raster: empty output path");
  const fs::path target(path);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::exists(dir, ec)) fail_write(path, "output directory '" + dir.string() + "' does not exist");
  if (!fs::is_directory(dir, ec)) fail_write(path, "'" + dir.string() + "' is not a directory");
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    fail_write(path, "output directory '" + dir.string() + "' is not writable");
  if (fs::is_directory(target, ec)) fail_write(path, "the output path is a directory");
  if (!options.overwrite && fs::exists(target, ec)) fail_write(path, "the file exists", "overwrite");
}

void check_layout(const std::string& path, int width, int height, int bands, GDALDataType type,
                  const RasterWriteOptions& options) {
  if (width < 1 || height < 1) fail_write(path, "raster size must be at least 1×1");
  if (bands < 1) fail_write(path, "a raster needs at least one band");
  if (!options.band_descriptions.empty() && static_cast<int>(options.band_descriptions.size()) != bands)
    fail_write(path, std::to_string(options.band_descriptions.size()) + " band descriptions for " +
                         std::to_string(bands) + " bands");
  for (const auto& co : options.creation_options)
    if (co.find('=') == std::string::npos || co.front() == '=')
      fail_write(path, "creation option '" + co + "' is not NAME=VALUE");
  if (options.nodata && type == GDT_Byte &&
      (!(*options.nodata >= 0 && *options.nodata <= 255) || *options.nodata != std::floor(*options.nodata)))
    fail_write(path, "nodata value must be an integer 0…255 for 8-bit output");
}

GDALDriver& writable_driver(const std::string& path, GDALDataType type, const RasterWriteOptions& options,
                            const CslList& creation_options) {
  ensure_gdal_registered();
  auto* driver = GetGDALDriverManager()->GetDriverByName(options.format.c_str());
  if (!driver || !driver->GetMetadataItem(GDAL_DCAP_RASTER))
    fail_write(path, "unknown raster format '" + options.format + "' (try GTiff, COG or PNG)");
  if (!driver->GetMetadataItem(GDAL_DCAP_CREATE) && !driver->GetMetadataItem(GDAL_DCAP_CREATECOPY))
    fail_write(path, "GDAL cannot write the " + options.format + " format");
  const char* types = driver->GetMetadataItem(GDAL_DMD_CREATIONDATATYPES);
  const std::string type_name = GDALGetDataTypeName(type);
  std::string padded(" ");  // (built stepwise: GCC 12 warns falsely on " " + string)
  padded.append(types ? types : "").push_back(' ');
  if (types && padded.find(' ' + type_name + ' ') == std::string::npos)
    fail_write(path, options.format + " cannot store " + type_name + " data (it supports " + types +
                         "); use GTiff or COG");
  GdalErrorCapture capture;
  if (!options.creation_options.empty() && !GDALValidateCreationOptions(driver, creation_options.get()))
    fail_write(path, "invalid creation option for " + options.format + ": " +
                         (capture.warnings().empty() ? capture.failure() : capture.warnings().back()));
  return *driver;
}

bool creates_directly(GDALDriver& driver, const std::string& format) {
  return driver.GetMetadataItem(GDAL_DCAP_CREATE) && lower_name(format) != "cog";
}

StagingDir::StagingDir(const std::string& target) : target_(target) {
  if (is_virtual(target)) return;
  static std::atomic<unsigned> counter{0};
  const fs::path dir = target_.has_parent_path() ? target_.parent_path() : fs::path(".");
  path_ = dir / (".skylit-tmp-" + target_.filename().string() + "-" + std::to_string(::getpid()) + "-" +
                 std::to_string(counter++));
  std::error_code ec;
  if (!fs::create_directory(path_, ec)) {
    path_.clear();
    fail_write(target, "cannot create a temporary folder in '" + dir.string() + "': " + ec.message());
  }
}

StagingDir::~StagingDir() {
  std::error_code ec;
  if (!path_.empty()) fs::remove_all(path_, ec);
}

std::string StagingDir::file(const std::string& name) const {
  if (path_.empty()) return "/vsimem/.skylit-stage-" + std::to_string(::getpid()) + "-" + name;
  return (path_ / name).string();
}

std::string StagingDir::target_file() const {
  return path_.empty() ? target_.string() : file(target_.filename().string());
}

void StagingDir::publish() {
  if (path_.empty()) return;
  const fs::path dir = target_.has_parent_path() ? target_.parent_path() : fs::path(".");
  std::error_code ec;
  std::vector<fs::path> sidecars;
  for (const auto& entry : fs::directory_iterator(path_))
    if (entry.path().filename() != target_.filename()) sidecars.push_back(entry.path());
  // A stale .aux.xml of an older output would override the new file's metadata.
  const fs::path old_aux = dir / (target_.filename().string() + ".aux.xml");
  if (!fs::exists(path_ / old_aux.filename(), ec)) fs::remove(old_aux, ec);
  try {
    for (const auto& s : sidecars) fs::rename(s, dir / s.filename());
    fs::rename(path_ / target_.filename(), target_);
    fs::remove(path_);  // empty now
    path_.clear();
  } catch (const fs::filesystem_error& e) {
    fail_write(target_.string(), e.what());
  }
}

void describe_dataset(GDALDataset& ds, const std::string& path, const GeoReference& georef, int bands,
                      GDALDataType type, const RasterWriteOptions& options) {
  if (georef.has_geotransform) {
    double gt[6];
    std::copy(georef.geotransform.begin(), georef.geotransform.end(), gt);
    ds.SetGeoTransform(gt);
  }
  if (!georef.crs_wkt.empty()) {
    OGRSpatialReference srs;
    if (srs.importFromWkt(georef.crs_wkt.c_str()) != OGRERR_NONE) fail_write(path, "invalid CRS WKT");
    ds.SetSpatialRef(&srs);
  }
  for (int b = 1; b <= bands; ++b) {
    GDALRasterBand* band = ds.GetRasterBand(b);
    if (options.nodata) band->SetNoDataValue(*options.nodata);
    if (!options.band_descriptions.empty()) band->SetDescription(options.band_descriptions[b - 1].c_str());
    if (type == GDT_Byte) {
      static const GDALColorInterp gray[] = {GCI_GrayIndex, GCI_AlphaBand};
      static const GDALColorInterp rgba[] = {GCI_RedBand, GCI_GreenBand, GCI_BlueBand, GCI_AlphaBand};
      if (bands <= 2) band->SetColorInterpretation(gray[b - 1]);
      else if (bands <= 4) band->SetColorInterpretation(rgba[b - 1]);
    }
  }
}

}  // namespace skylit::terrain::detail
