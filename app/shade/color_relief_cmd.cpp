#include "app/shade/color_relief_cmd.h"

#include "terrain/raster_writer.h"

#include <gdal_priv.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <span>
#include <stdexcept>
#include <vector>

namespace skylit::app::shade {
namespace {

struct DatasetCloser {
  void operator()(GDALDataset* d) const { GDALClose(d); }
};
using Dataset = std::unique_ptr<GDALDataset, DatasetCloser>;

constexpr const char* kRampNames[] = {"hypsometric", "grey", "bathymetry"};

}  // namespace

std::string resolve_color_file(const std::string& name) {
  if (std::filesystem::exists(name)) return name;
  std::string names;
  for (const char* r : kRampNames) {
    if (name == r) return std::string(SKYLIT_DATA_DIR) + "/ramps/" + r + ".txt";
    names += (names.empty() ? "" : ", ") + std::string(r);
  }
  throw std::invalid_argument("--color " + name + ": no such file, and no ramp of that name (" + names + ")");
}

int run_color_relief(const ColorReliefArgs& a) {
  if (a.color_file.empty()) throw std::invalid_argument("-p color-relief needs --color FILE");
  if (a.output.empty()) throw std::invalid_argument("-p color-relief needs an OUTPUT path");
  if (std::filesystem::exists(a.output) && !a.overwrite)
    throw std::invalid_argument(a.output + " exists (use --overwrite)");
  GDALAllRegister();
  Dataset src(static_cast<GDALDataset*>(GDALOpen(a.input.c_str(), GA_ReadOnly)));
  if (!src) throw std::runtime_error("cannot open " + a.input);
  GDALRasterBand* band = src->GetRasterBand(1);
  const int w = src->GetRasterXSize();
  const int h = src->GetRasterYSize();
  // gdaldem reads every type but Byte/Int16/UInt16 (exact either way) as Float32.
  std::vector<float> z(static_cast<std::size_t>(w) * h);
  if (band->RasterIO(GF_Read, 0, 0, w, h, z.data(), w, h, GDT_Float32, 0, 0) != CE_None)
    throw std::runtime_error("cannot read " + a.input);
  int has_nodata = 0;
  const double nodata = band->GetNoDataValue(&has_nodata);
  relief::SourceInfo info;
  if (has_nodata) info.nodata = nodata;
  info.min_max = [&]() {
    int ok_min = 0, ok_max = 0;
    double lo = band->GetMinimum(&ok_min), hi = band->GetMaximum(&ok_max);  // stored statistics first
    if (ok_min && ok_max) return std::pair(lo, hi);
    lo = std::numeric_limits<double>::infinity();
    hi = -lo;
    for (const float v : z) {
      if (std::isnan(v) || (has_nodata && static_cast<double>(v) == nodata)) continue;
      lo = std::min(lo, static_cast<double>(v));
      hi = std::max(hi, static_cast<double>(v));
    }
    if (!(lo <= hi)) throw std::invalid_argument(a.input + " has no valid heights for a percentage");
    return std::pair(lo, hi);
  };
  const relief::ColorTable table = relief::read_color_table(resolve_color_file(a.color_file), info);

  const int nb = a.alpha ? 4 : 3;
  std::vector<std::uint8_t> out(static_cast<std::size_t>(nb) * w * h);
  const std::size_t plane = static_cast<std::size_t>(w) * h;
  for (std::size_t k = 0; k < plane; ++k) {
    const relief::Rgba c = relief::color_at(table, static_cast<double>(z[k]), a.selection);
    for (int b = 0; b < nb; ++b) out[b * plane + k] = c[b];
  }

  terrain::GeoReference georef;
  georef.has_geotransform = src->GetGeoTransform(georef.geotransform.data()) == CE_None;
  if (const OGRSpatialReference* srs = src->GetSpatialRef()) {
    char* wkt = nullptr;
    if (srs->exportToWkt(&wkt) == OGRERR_NONE && wkt) georef.crs_wkt = wkt;
    CPLFree(wkt);
  }
  terrain::RasterWriteOptions options;
  options.format = "GTiff";
  terrain::write_raster(a.output, georef, w, h, nb, std::span<const std::uint8_t>(out), options);
  return 0;
}

}  // namespace skylit::app::shade
