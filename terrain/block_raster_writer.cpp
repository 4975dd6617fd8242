#include "terrain/block_raster_writer.h"

#include "terrain/gdal_util.h"
#include "terrain/raster_output.h"

namespace skylit::terrain {
namespace {

using detail::DatasetPtr;
using detail::fail_write;

GDALDataType gdal_type(BlockRasterWriter::Sample s) {
  return s == BlockRasterWriter::Sample::Byte ? GDT_Byte : GDT_Float32;
}

// A write failure's message: a full disk said plainly (GDAL's last message is often the
// TIFF layer's "write error at scanline …" after the system's "No space left").
std::string write_failure(const detail::GdalErrorCapture& capture) {
  for (const std::string& f : capture.failures())
    if (f.find("No space left") != std::string::npos) return "the disk is full (No space left on device)";
  return capture.failure("GDAL write error");
}

int CPL_STDCALL progress_trampoline(double done, const char*, void* user) {
  return (*static_cast<const std::function<bool(double)>*>(user))(done) ? TRUE : FALSE;
}

}  // namespace

struct BlockRasterWriter::State {
  std::string path;
  int width = 0, height = 0, bands = 0;
  Sample sample;
  RasterWriteOptions options;
  detail::CslList creation_options;
  GDALDriver* driver = nullptr;
  bool direct = false;
  detail::StagingDir staging;
  DatasetPtr ds;

  State(const std::string& p, const RasterWriteOptions& o) : path(p), options(o), staging(p) {}
};

BlockRasterWriter::BlockRasterWriter(const std::string& path, const GeoReference& georef, int width, int height,
                                     int bands, Sample sample, const RasterWriteOptions& options) {
  if (options.layout != SampleLayout::BandSequential) fail_write(path, "blocks are written band-sequential");
  const GDALDataType type = gdal_type(sample);
  detail::check_layout(path, width, height, bands, type, options);
  detail::check_target(path, options);
  detail::CslList co;
  for (const auto& c : options.creation_options) co.add(c);
  GDALDriver& driver = detail::writable_driver(path, type, options, co);
  state_ = std::make_unique<State>(path, options);
  State& s = *state_;
  s.width = width;
  s.height = height;
  s.bands = bands;
  s.sample = sample;
  for (const auto& c : options.creation_options) s.creation_options.add(c);
  s.driver = &driver;
  s.direct = detail::creates_directly(driver, options.format);
  detail::GdalErrorCapture capture;
  if (s.direct) {
    s.ds.reset(driver.Create(s.staging.target_file().c_str(), width, height, bands, type, s.creation_options.get()));
  } else {
    // Tiled, so that blocks land in few disk blocks; BigTIFF where 4 GB may be passed.
    detail::CslList stage_options;
    for (const char* o : {"TILED=YES", "BLOCKXSIZE=512", "BLOCKYSIZE=512", "BIGTIFF=IF_SAFER", "INTERLEAVE=BAND"})
      stage_options.add(o);
    GDALDriver* gtiff = GetGDALDriverManager()->GetDriverByName("GTiff");
    s.ds.reset(gtiff->Create(s.staging.file("stage.tif").c_str(), width, height, bands, type, stage_options.get()));
  }
  if (!s.ds) fail_write(path, capture.failure("the driver refused to create the file"));
  detail::describe_dataset(*s.ds, path, georef, bands, type, options);
}

BlockRasterWriter::~BlockRasterWriter() {
  if (state_ && state_->ds) {
    detail::GdalErrorCapture abandoned;  // an unfinished file's close errors (a full disk) are moot
    state_->ds.reset();
  }
}

void BlockRasterWriter::write(const PixelRect& rect, std::span<const float> data) {
  write_any(rect, data.data(), data.size(), Sample::Float32);
}

void BlockRasterWriter::write(const PixelRect& rect, std::span<const std::uint8_t> data) {
  write_any(rect, data.data(), data.size(), Sample::Byte);
}

void BlockRasterWriter::write_any(const PixelRect& rect, const void* data, std::size_t values, Sample sample) {
  State& s = *state_;
  if (!s.ds) fail_write(s.path, "the raster was already finished");
  if (sample != s.sample) fail_write(s.path, "a block of the wrong sample type");
  if (rect.empty() || rect.x0 < 0 || rect.y0 < 0 || rect.x1() > s.width || rect.y1() > s.height)
    fail_write(s.path, "a block outside the raster");
  if (values != static_cast<std::size_t>(rect.width) * rect.height * s.bands)
    fail_write(s.path, "a block's sample count does not match its size");
  detail::GdalErrorCapture capture;
  const GDALDataType type = gdal_type(sample);
  const GSpacing size = GDALGetDataTypeSizeBytes(type);
  if (s.ds->RasterIO(GF_Write, rect.x0, rect.y0, rect.width, rect.height, const_cast<void*>(data), rect.width,
                     rect.height, type, s.bands, nullptr, size, size * rect.width,
                     size * rect.width * rect.height, nullptr) != CE_None)
    fail_write(s.path, write_failure(capture));
  s.ds->FlushCache();  // a full disk fails here, at this block, not at finish()
  if (capture.has_failure()) fail_write(s.path, write_failure(capture));
}

void BlockRasterWriter::finish() {
  State& s = *state_;
  if (!s.ds) fail_write(s.path, "the raster was already finished");
  detail::GdalErrorCapture capture;
  if (s.direct) {
    s.ds.reset();  // flushes and closes
  } else {
    const bool has_progress = static_cast<bool>(s.options.progress);
    DatasetPtr out(s.driver->CreateCopy(s.staging.target_file().c_str(), s.ds.get(), FALSE,
                                        s.creation_options.get(),
                                        has_progress ? progress_trampoline : GDALDummyProgress,
                                        has_progress ? &s.options.progress : nullptr));
    if (!out) fail_write(s.path, capture.has_failure() ? write_failure(capture) : "the driver could not write the file");
    out.reset();
    s.ds.reset();
    VSIUnlink(s.staging.file("stage.tif").c_str());
  }
  if (capture.has_failure()) fail_write(s.path, write_failure(capture));
  s.staging.publish();
}

}  // namespace skylit::terrain
