// The warper's copy of a DEM: filled a strip at a time, in memory or in a temporary
// GeoTIFF that is unlinked once reopened.
#include "terrain/staged_dem.h"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <span>

#include "terrain/gdal_util.h"

namespace skylit::terrain {
namespace {

using detail::DatasetPtr;
using detail::GdalErrorCapture;

std::filesystem::path staging_path(const StagingOptions& o) {
  static std::atomic<int> counter{0};
  const std::filesystem::path dir = o.directory.empty() ? std::filesystem::temp_directory_path() : o.directory;
  return dir / ("skylit-staged-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ".tif");
}

DatasetPtr create(const std::filesystem::path& path, int width, int height) {
  GdalErrorCapture capture;
  const bool disk = !path.empty();
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(disk ? "GTiff" : "MEM");
  if (!driver) throw DemError(std::string("GDAL's ") + (disk ? "GTiff" : "MEM") + " driver is missing");
  const char* tiff_options[] = {"TILED=YES", "BLOCKXSIZE=256", "BLOCKYSIZE=256", "COMPRESS=NONE",
                                "BIGTIFF=IF_SAFER", "SPARSE_OK=FALSE", nullptr};
  DatasetPtr ds(driver->Create(disk ? path.c_str() : "", width, height, 1, GDT_Float32,
                               disk ? const_cast<char**>(tiff_options) : nullptr));
  if (!ds)
    throw DemError(disk ? "cannot create the DEM's staged copy '" + path.string() + "': " + capture.failure()
                        : "cannot create the in-memory DEM copy: " + capture.failure());
  return ds;
}

// Once written: where it lies, and NaN as its nodata value if it has voids (the warper
// then skips them; without voids the band has none, as the source DEM).
void describe(GDALDataset& ds, const GeoReference& georef, bool voids) {
  GdalErrorCapture capture;
  std::array<double, 6> gt = georef.geotransform;
  if (ds.SetGeoTransform(gt.data()) != CE_None || ds.SetProjection(georef.crs_wkt.c_str()) != CE_None ||
      (voids && ds.GetRasterBand(1)->SetNoDataValue(std::numeric_limits<double>::quiet_NaN()) != CE_None))
    throw DemError("cannot georeference the DEM's staged copy: " + capture.failure());
}

// Rows first_row… of `ds` (`width` wide), NaN where not valid; `values` is scratch.
void write_rows(GDALDataset& ds, std::span<const float> heights, std::span<const std::uint8_t> valid, int width,
                int first_row, std::vector<float>& values) {
  values.assign(heights.begin(), heights.end());
  for (std::size_t k = 0; k < values.size(); ++k)
    if (!valid[k]) values[k] = std::numeric_limits<float>::quiet_NaN();
  const int rows = static_cast<int>(values.size() / width);
  GdalErrorCapture capture;
  if (ds.GetRasterBand(1)->RasterIO(GF_Write, 0, first_row, width, rows, values.data(), width, rows, GDT_Float32, 0,
                                    0, nullptr) != CE_None)
    throw DemError("cannot write the DEM's staged copy (rows " + std::to_string(first_row) + "…): " +
                   capture.failure("disk full?"));
}

std::string megabytes(std::uintmax_t bytes) { return std::to_string((bytes + (1u << 19)) >> 20) + " MiB"; }

// A full disk shows only when GDAL flushes its cache, as a TIFF error: say so before.
void check_space(const std::filesystem::path& dir, std::uintmax_t bytes) {
  std::error_code ec;
  const std::filesystem::space_info space = std::filesystem::space(dir, ec);
  if (ec)
    throw DemError("cannot stage the DEM in '" + dir.string() + "': " + ec.message(), "memory_limit_bytes");
  const std::uintmax_t need = bytes + bytes / 64 + (std::uintmax_t{1} << 20);  // and the TIFF's block tables
  if (space.available < need)
    throw DemError("the DEM's staged copy needs " + megabytes(need) + " in '" + dir.string() + "', which has " +
                       megabytes(space.available) + " free",
                   "memory_limit_bytes");
}

}  // namespace

struct StagedDem::Impl {
  HeightField outline;
  DatasetPtr dataset;
  std::size_t valid_count = 0;
  float centre_height = 0.0f;
  bool on_disk = false;
};

StagedDem::StagedDem(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
StagedDem::~StagedDem() = default;
StagedDem::StagedDem(StagedDem&&) noexcept = default;
StagedDem& StagedDem::operator=(StagedDem&&) noexcept = default;

const HeightField& StagedDem::outline() const { return impl_->outline; }
std::size_t StagedDem::valid_count() const { return impl_->valid_count; }
float StagedDem::centre_height() const { return impl_->centre_height; }
bool StagedDem::on_disk() const { return impl_->on_disk; }
GDALDataset& StagedDem::dataset() const { return *impl_->dataset; }

StagedDem StagedDem::from_field(const HeightField& field) {
  const std::size_t n = static_cast<std::size_t>(field.width) * field.height;
  if (field.width < 1 || field.height < 1 || field.heights.size() != n || field.valid.size() != n ||
      static_cast<int>(field.dx_per_row.size()) != field.height)
    throw DemError("staged DEM: the height field's arrays do not match its size");
  detail::ensure_gdal_registered();
  auto impl = std::make_unique<Impl>();
  impl->valid_count = static_cast<std::size_t>(std::count(field.valid.begin(), field.valid.end(), 1));
  impl->dataset = create({}, field.width, field.height);
  const int cx = field.width / 2, cy = field.height / 2;
  float lowest = std::numeric_limits<float>::infinity();
  for (std::size_t k = 0; k < n; ++k)
    if (field.valid[k]) lowest = std::min(lowest, field.heights[k]);
  impl->centre_height = field.is_valid(cx, cy) ? field.at(cx, cy) : (impl->valid_count > 0 ? lowest : 0.0f);
  // In strips: a whole NaN-marked copy would add 4 B a pixel to the peak.
  const int rows = static_cast<int>(std::max<std::size_t>(1, StagingOptions{}.strip_pixels / field.width));
  std::vector<float> values;
  for (int j0 = 0; j0 < field.height; j0 += rows) {
    const std::size_t first = static_cast<std::size_t>(j0) * field.width;
    const std::size_t count = static_cast<std::size_t>(std::min(rows, field.height - j0)) * field.width;
    write_rows(*impl->dataset, std::span(field.heights).subspan(first, count),
               std::span(field.valid).subspan(first, count), field.width, j0, values);
  }
  describe(*impl->dataset, field.georef, impl->valid_count < n);
  impl->outline = field;
  impl->outline.heights = {};
  impl->outline.valid = {};
  return StagedDem(std::move(impl));
}

StagedDem StagedDem::read(const std::vector<std::string>& paths, const DemReadOptions& read,
                          const StagingOptions& staging, std::vector<std::string>& warnings,
                          const std::function<void(double)>& progress) {
  const DemInfo info = inspect_dem(paths);
  const std::size_t pixels = static_cast<std::size_t>(info.width) * info.height;
  auto impl = std::make_unique<Impl>();
  impl->on_disk = pixels * sizeof(float) > staging.memory_limit_bytes;
  const std::filesystem::path path = impl->on_disk ? staging_path(staging) : std::filesystem::path();
  if (impl->on_disk) check_space(path.parent_path(), pixels * sizeof(float));
  const int cx = info.width / 2, cy = info.height / 2;
  std::vector<float> values;
  const int rows = static_cast<int>(std::max<std::size_t>(1, staging.strip_pixels / std::max(1, info.width)));
  DemReadResult whole;
  std::size_t rows_read = 0;
  try {
    whole = read_dem_in_strips(paths, read, rows, [&](const HeightField& strip, int first_row) {
      if (!impl->dataset) impl->dataset = create(path, info.width, info.height);
      write_rows(*impl->dataset, strip.heights, strip.valid, strip.width, first_row, values);
      if (cy >= first_row && cy < first_row + strip.height && strip.is_valid(cx, cy - first_row))
        impl->centre_height = strip.at(cx, cy - first_row);
      else if (cy >= first_row && cy < first_row + strip.height)
        impl->centre_height = std::numeric_limits<float>::quiet_NaN();
      rows_read += static_cast<std::size_t>(strip.height);
      if (progress) progress(static_cast<double>(rows_read) / info.height);
    });
    describe(*impl->dataset, whole.field.georef, whole.nodata_count > 0);
  } catch (...) {
    impl->dataset.reset();
    std::error_code ec;
    if (!path.empty()) std::filesystem::remove(path, ec);
    throw;
  }
  impl->valid_count = pixels - whole.nodata_count;
  if (std::isnan(impl->centre_height)) impl->centre_height = static_cast<float>(whole.min_height);
  if (impl->on_disk) {
    GdalErrorCapture capture;
    impl->dataset.reset();  // flushes and closes the file
    if (!capture.has_failure())
      impl->dataset.reset(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
    std::error_code ec;
    std::filesystem::remove(path, ec);
    std::filesystem::remove(path.string() + ".aux.xml", ec);
    if (!impl->dataset)
      throw DemError("cannot write or reopen the DEM's staged copy '" + path.string() + "' (is its disk full?): " +
                         capture.failure(),
                     "memory_limit_bytes");
  }
  warnings.insert(warnings.end(), whole.warnings.begin(), whole.warnings.end());
  impl->outline = std::move(whole.field);
  return StagedDem(std::move(impl));
}

}  // namespace skylit::terrain
