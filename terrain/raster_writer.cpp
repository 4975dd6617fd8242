// Atomic GDAL raster output: build in a hidden temporary folder next to the target,
// rename into place when complete, delete everything on failure.
#include "terrain/raster_writer.h"

#include <cpl_string.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "terrain/gdal_util.h"

namespace skylit::terrain {
namespace {

namespace fs = std::filesystem;
using detail::DatasetPtr;
using detail::GdalErrorCapture;

struct Request {
  const std::string& path;
  const GeoReference& georef;
  int width, height, bands;
  GDALDataType type;
  const void* data;
  const RasterWriteOptions& options;
};

std::string lower_name(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

[[noreturn]] void fail(const std::string& path, const std::string& what, std::string option = {}) {
  throw RasterWriteError("cannot write '" + path + "': " + what, std::move(option));
}

class CslList {  // owns a GDAL string list
 public:
  ~CslList() { CSLDestroy(list_); }
  void add(const std::string& s) { list_ = CSLAddString(list_, s.c_str()); }
  char** get() const { return list_; }

 private:
  char** list_ = nullptr;
};

// Removes the temporary folder unless released.
class TempDir {
 public:
  explicit TempDir(fs::path p) : path_(std::move(p)) {}
  ~TempDir() {
    std::error_code ec;
    if (!path_.empty()) fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

struct ProgressBridge {
  const std::function<bool(double)>* callback;
  double base, span;  // maps GDAL's [0, 1] onto [base, base + span]
};

int CPL_STDCALL progress_trampoline(double done, const char*, void* user) {
  auto* p = static_cast<ProgressBridge*>(user);
  return (*p->callback)(p->base + p->span * done) ? TRUE : FALSE;
}

GDALDriver* find_driver(const Request& r) {
  auto* driver = GetGDALDriverManager()->GetDriverByName(r.options.format.c_str());
  if (!driver || !driver->GetMetadataItem(GDAL_DCAP_RASTER))
    fail(r.path, "unknown raster format '" + r.options.format + "' (try GTiff, COG or PNG)");
  if (!driver->GetMetadataItem(GDAL_DCAP_CREATE) && !driver->GetMetadataItem(GDAL_DCAP_CREATECOPY))
    fail(r.path, "GDAL cannot write the " + r.options.format + " format");
  const char* types = driver->GetMetadataItem(GDAL_DMD_CREATIONDATATYPES);
  const std::string type_name = GDALGetDataTypeName(r.type);
  std::string padded(" ");  // (built stepwise: GCC 12 warns falsely on " " + string)
  padded.append(types ? types : "").push_back(' ');
  if (types && padded.find(' ' + type_name + ' ') == std::string::npos)
    fail(r.path, r.options.format + " cannot store " + type_name + " data (it supports " + types +
                     "); use GTiff or COG");
  return driver;
}

void check_target(const Request& r) {
  if (r.path.empty()) throw RasterWriteError("cannot write a raster: empty output path");
  const fs::path target(r.path);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::exists(dir, ec)) fail(r.path, "output directory '" + dir.string() + "' does not exist");
  if (!fs::is_directory(dir, ec)) fail(r.path, "'" + dir.string() + "' is not a directory");
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    fail(r.path, "output directory '" + dir.string() + "' is not writable");
  if (fs::is_directory(target, ec)) fail(r.path, "the output path is a directory");
  if (!r.options.overwrite && fs::exists(target, ec))
    fail(r.path, "the file exists", "overwrite");
}

void check_request(const Request& r) {
  if (r.width < 1 || r.height < 1) fail(r.path, "raster size must be at least 1×1");
  if (r.bands < 1) fail(r.path, "a raster needs at least one band");
  if (!r.options.band_descriptions.empty() &&
      static_cast<int>(r.options.band_descriptions.size()) != r.bands)
    fail(r.path, std::to_string(r.options.band_descriptions.size()) + " band descriptions for " +
                     std::to_string(r.bands) + " bands");
  for (const auto& co : r.options.creation_options)
    if (co.find('=') == std::string::npos || co.front() == '=')
      fail(r.path, "creation option '" + co + "' is not NAME=VALUE");
  if (r.options.nodata && r.type == GDT_Byte &&
      (!(*r.options.nodata >= 0 && *r.options.nodata <= 255) || *r.options.nodata != std::floor(*r.options.nodata)))
    fail(r.path, "nodata value must be an integer 0…255 for 8-bit output");
}

// Georeference, nodata, descriptions and colour interpretation, then the pixels.
void fill_dataset(GDALDataset& ds, const Request& r, double progress_span) {
  if (r.georef.has_geotransform) {
    double gt[6];
    std::copy(r.georef.geotransform.begin(), r.georef.geotransform.end(), gt);
    ds.SetGeoTransform(gt);
  }
  if (!r.georef.crs_wkt.empty()) {
    OGRSpatialReference srs;
    if (srs.importFromWkt(r.georef.crs_wkt.c_str()) != OGRERR_NONE) fail(r.path, "invalid CRS WKT");
    ds.SetSpatialRef(&srs);
  }
  for (int b = 1; b <= r.bands; ++b) {
    GDALRasterBand* band = ds.GetRasterBand(b);
    if (r.options.nodata) band->SetNoDataValue(*r.options.nodata);
    if (!r.options.band_descriptions.empty()) band->SetDescription(r.options.band_descriptions[b - 1].c_str());
    if (r.type == GDT_Byte) {
      static const GDALColorInterp gray[] = {GCI_GrayIndex, GCI_AlphaBand};
      static const GDALColorInterp rgba[] = {GCI_RedBand, GCI_GreenBand, GCI_BlueBand, GCI_AlphaBand};
      if (r.bands <= 2) band->SetColorInterpretation(gray[b - 1]);
      else if (r.bands <= 4) band->SetColorInterpretation(rgba[b - 1]);
    }
  }
  const int size = GDALGetDataTypeSizeBytes(r.type);
  const bool interleaved = r.options.layout == SampleLayout::PixelInterleaved;
  const GSpacing pixel = interleaved ? static_cast<GSpacing>(size) * r.bands : size;
  const GSpacing line = pixel * r.width;
  const GSpacing band_space = interleaved ? size : line * r.height;
  // Strips of rows, so that progress moves and a cancel is honoured promptly.
  const int strip = std::max(1, std::min(r.height, (1 << 20) / std::max(1, r.width)));
  for (int j0 = 0; j0 < r.height; j0 += strip) {
    const int rows = std::min(strip, r.height - j0);
    auto* src = static_cast<const std::uint8_t*>(r.data) + static_cast<std::size_t>(j0) * line;
    if (ds.RasterIO(GF_Write, 0, j0, r.width, rows, const_cast<std::uint8_t*>(src), r.width, rows, r.type,
                    r.bands, nullptr, pixel, line, band_space, nullptr) != CE_None)
      fail(r.path, "GDAL write error");
    if (r.options.progress && !r.options.progress(progress_span * (j0 + rows) / r.height))
      fail(r.path, "cancelled");
  }
}

// Moves every file of the temporary folder next to the target (sidecars first, the
// raster itself last, so a reader never sees the raster without its .aux.xml).
void publish(const fs::path& tmp, const fs::path& target) {
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  std::vector<fs::path> sidecars;
  for (const auto& entry : fs::directory_iterator(tmp)) {
    if (entry.path().filename() != target.filename()) sidecars.push_back(entry.path());
  }
  // A stale .aux.xml of an older output would override the new file's metadata.
  const fs::path old_aux = dir / (target.filename().string() + ".aux.xml");
  if (!fs::exists(tmp / old_aux.filename(), ec)) fs::remove(old_aux, ec);
  for (const auto& s : sidecars) fs::rename(s, dir / s.filename());
  fs::rename(tmp / target.filename(), target);
}

void write_any(const Request& r) {
  check_request(r);
  check_target(r);
  detail::ensure_gdal_registered();
  GDALDriver* driver = find_driver(r);

  CslList co;
  for (const auto& c : r.options.creation_options) co.add(c);
  GdalErrorCapture capture;
  if (!r.options.creation_options.empty() && !GDALValidateCreationOptions(driver, co.get()))
    fail(r.path, "invalid creation option for " + r.options.format + ": " +
                     (capture.warnings().empty() ? capture.failure() : capture.warnings().back()));

  const fs::path target(r.path);
  const bool virtual_path = r.path.rfind("/vsi", 0) == 0;
  static std::atomic<unsigned> counter{0};
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  TempDir tmp(virtual_path ? fs::path() : dir / (".skylit-tmp-" + target.filename().string() + "-" +
                                                  std::to_string(::getpid()) + "-" + std::to_string(counter++)));
  std::error_code ec;
  if (!virtual_path && !fs::create_directory(tmp.path(), ec))
    fail(r.path, "cannot create a temporary folder in '" + dir.string() + "': " + ec.message());
  const std::string out_name = virtual_path ? r.path : (tmp.path() / target.filename()).string();

  try {
    // COG and PNG (and other copy-only drivers) are produced from an in-memory raster.
    const bool direct = driver->GetMetadataItem(GDAL_DCAP_CREATE) && lower_name(r.options.format) != "cog";
    if (direct) {
      DatasetPtr ds(driver->Create(out_name.c_str(), r.width, r.height, r.bands, r.type, co.get()));
      if (!ds) fail(r.path, capture.failure("the driver refused to create the file"));
      fill_dataset(*ds, r, 1.0);
      ds.reset();  // flushes and closes
    } else {
      GDALDriver* mem = GetGDALDriverManager()->GetDriverByName("MEM");
      DatasetPtr src(mem->Create("", r.width, r.height, r.bands, r.type, nullptr));
      if (!src) fail(r.path, "out of memory");
      fill_dataset(*src, r, 0.5);
      ProgressBridge bridge{&r.options.progress, 0.5, 0.5};
      const bool has_progress = static_cast<bool>(r.options.progress);
      DatasetPtr ds(driver->CreateCopy(out_name.c_str(), src.get(), FALSE, co.get(),
                                       has_progress ? progress_trampoline : GDALDummyProgress,
                                       has_progress ? &bridge : nullptr));
      if (!ds) fail(r.path, capture.failure("the driver could not write the file"));
      ds.reset();
    }
    if (capture.has_failure()) fail(r.path, capture.failure());
    if (!virtual_path) publish(tmp.path(), target);
  } catch (const fs::filesystem_error& e) {
    fail(r.path, e.what());
  }
  if (r.options.progress) r.options.progress(1.0);
}

}  // namespace

void write_raster(const std::string& path, const GeoReference& georef, int width, int height, int bands,
                  std::span<const float> data, const RasterWriteOptions& options) {
  if (data.size() != static_cast<std::size_t>(width) * height * bands)
    fail(path, "data holds " + std::to_string(data.size()) + " values, expected width·height·bands");
  write_any({path, georef, width, height, bands, GDT_Float32, data.data(), options});
}

void write_raster(const std::string& path, const GeoReference& georef, int width, int height, int bands,
                  std::span<const std::uint8_t> data, const RasterWriteOptions& options) {
  if (data.size() != static_cast<std::size_t>(width) * height * bands)
    fail(path, "data holds " + std::to_string(data.size()) + " values, expected width·height·bands");
  write_any({path, georef, width, height, bands, GDT_Byte, data.data(), options});
}

void write_height_field(const std::string& path, const HeightField& field, const RasterWriteOptions& options) {
  const double nodata = field.nodata.value_or(-32768.0);
  std::vector<float> out(field.heights);
  bool any_void = false;
  for (std::size_t k = 0; k < out.size(); ++k)
    if (!field.valid[k]) {
      out[k] = static_cast<float>(nodata);
      any_void = true;
    }
  RasterWriteOptions o = options;
  if (field.nodata || any_void) o.nodata = nodata;
  write_raster(path, field.georef, field.width, field.height, 1, std::span<const float>(out), o);
}

}  // namespace skylit::terrain
