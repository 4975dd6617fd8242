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
#include "terrain/raster_output.h"

namespace skylit::terrain {
namespace {

using detail::CslList;
using detail::DatasetPtr;
using detail::GdalErrorCapture;
using detail::fail_write;

struct Request {
  const std::string& path;
  const GeoReference& georef;
  int width, height, bands;
  GDALDataType type;
  const void* data;
  const RasterWriteOptions& options;
};

struct ProgressBridge {
  const std::function<bool(double)>* callback;
  double base, span;  // maps GDAL's [0, 1] onto [base, base + span]
};

int CPL_STDCALL progress_trampoline(double done, const char*, void* user) {
  auto* p = static_cast<ProgressBridge*>(user);
  return (*p->callback)(p->base + p->span * done) ? TRUE : FALSE;
}

// Georeference and band metadata, then the pixels.
void fill_dataset(GDALDataset& ds, const Request& r, double progress_span) {
  detail::describe_dataset(ds, r.path, r.georef, r.bands, r.type, r.options);
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
      fail_write(r.path, "GDAL write error");
    if (r.options.progress && !r.options.progress(progress_span * (j0 + rows) / r.height))
      fail_write(r.path, "cancelled");
  }
}

void write_any(const Request& r) {
  detail::check_layout(r.path, r.width, r.height, r.bands, r.type, r.options);
  detail::check_target(r.path, r.options);
  CslList co;
  for (const auto& c : r.options.creation_options) co.add(c);
  GDALDriver& driver = detail::writable_driver(r.path, r.type, r.options, co);
  detail::StagingDir staging(r.path);
  const std::string out_name = staging.target_file();
  GdalErrorCapture capture;
  // COG and PNG (and other copy-only drivers) are produced from an in-memory raster.
  if (detail::creates_directly(driver, r.options.format)) {
    DatasetPtr ds(driver.Create(out_name.c_str(), r.width, r.height, r.bands, r.type, co.get()));
    if (!ds) fail_write(r.path, capture.failure("the driver refused to create the file"));
    fill_dataset(*ds, r, 1.0);
    ds.reset();  // flushes and closes
  } else {
    GDALDriver* mem = GetGDALDriverManager()->GetDriverByName("MEM");
    DatasetPtr src(mem->Create("", r.width, r.height, r.bands, r.type, nullptr));
    if (!src) fail_write(r.path, "out of memory");
    fill_dataset(*src, r, 0.5);
    ProgressBridge bridge{&r.options.progress, 0.5, 0.5};
    const bool has_progress = static_cast<bool>(r.options.progress);
    DatasetPtr ds(driver.CreateCopy(out_name.c_str(), src.get(), FALSE, co.get(),
                                    has_progress ? progress_trampoline : GDALDummyProgress,
                                    has_progress ? &bridge : nullptr));
    if (!ds) fail_write(r.path, capture.failure("the driver could not write the file"));
    ds.reset();
  }
  if (capture.has_failure()) fail_write(r.path, capture.failure());
  staging.publish();
  if (r.options.progress) r.options.progress(1.0);
}

}  // namespace

void write_raster(const std::string& path, const GeoReference& georef, int width, int height, int bands,
                  std::span<const float> data, const RasterWriteOptions& options) {
  if (data.size() != static_cast<std::size_t>(width) * height * bands)
    fail_write(path, "data holds " + std::to_string(data.size()) + " values, expected width·height·bands");
  write_any({path, georef, width, height, bands, GDT_Float32, data.data(), options});
}

void write_raster(const std::string& path, const GeoReference& georef, int width, int height, int bands,
                  std::span<const std::uint8_t> data, const RasterWriteOptions& options) {
  if (data.size() != static_cast<std::size_t>(width) * height * bands)
    fail_write(path, "data holds " + std::to_string(data.size()) + " values, expected width·height·bands");
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
