// DEM reading: open (or mosaic), validate, read heights and mask, convert to metres,
// fill voids, attach metric spacing.
#include "terrain/dem_reader.h"

#include <cpl_conv.h>
#include <gdal_utils.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <sstream>

#include "terrain/gdal_util.h"
#include "terrain/nodata_fill.h"

namespace skylit::terrain {
namespace {

namespace fs = std::filesystem;
using detail::DatasetPtr;
using detail::GdalErrorCapture;

std::string fmt(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

bool is_virtual_path(const std::string& p) { return p.rfind("/vsi", 0) == 0; }

// Files that are never DEMs themselves although GDAL may identify them.
bool is_sidecar(const fs::path& p) {
  const std::string name = lower(p.filename().string());
  for (const char* suffix : {".aux.xml", ".ovr", ".msk", ".prj", ".tfw", ".wld", ".xml", ".txt", ".md"})
    if (name.size() >= std::string(suffix).size() &&
        name.compare(name.size() - std::string(suffix).size(), std::string::npos, suffix) == 0)
      return true;
  return false;
}

// A directory expands to the raster files GDAL recognises in it (sorted, so a mosaic
// is the same whatever the directory order).
std::vector<std::string> expand_inputs(const std::vector<std::string>& paths) {
  if (paths.empty()) throw DemError("no DEM file given");
  std::vector<std::string> files;
  for (const auto& p : paths) {
    if (is_virtual_path(p)) {
      files.push_back(p);
      continue;
    }
    std::error_code ec;
    if (fs::is_directory(p, ec)) {
      std::vector<std::string> found;
      for (const auto& entry : fs::directory_iterator(p, ec)) {
        if (!entry.is_regular_file() || is_sidecar(entry.path())) continue;
        GdalErrorCapture quiet;
        if (GDALIdentifyDriverEx(entry.path().c_str(), GDAL_OF_RASTER, nullptr, nullptr))
          found.push_back(entry.path().string());
      }
      if (ec) throw DemError("cannot list directory '" + p + "': " + ec.message());
      if (found.empty()) throw DemError("directory '" + p + "' holds no raster files");
      std::sort(found.begin(), found.end());
      files.insert(files.end(), found.begin(), found.end());
    } else if (!fs::exists(p, ec)) {
      throw DemError("DEM file '" + p + "' does not exist");
    } else {
      files.push_back(p);
    }
  }
  return files;
}

DatasetPtr open_raster(const std::string& path) {
  GdalErrorCapture capture;
  auto* ds = GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY | GDAL_OF_VERBOSE_ERROR);
  if (ds) return DatasetPtr(ds);
  // Tell "not a raster" apart from "unreadable".
  if (auto* vec = GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY)) {
    GDALClose(GDALDataset::ToHandle(vec));
    throw DemError("'" + path + "' is a vector dataset, not a raster DEM");
  }
  throw DemError("cannot open DEM '" + path + "': " +
                 capture.failure("not a raster format GDAL recognises, or the file is corrupt"));
}

void check_north_up(const std::string& name, const double gt[6]) {
  if (gt[2] != 0.0 || gt[4] != 0.0)
    throw DemError("DEM '" + name + "' has a rotated or sheared geotransform (terms " + fmt(gt[2]) +
                   ", " + fmt(gt[4]) + "); warp it to a north-up grid first (gdalwarp)");
}

// Mosaic of several tiles as an in-memory VRT. Tiles must share CRS, band count and
// pixel size, which GDALBuildVRT would otherwise silently skip or resample.
DatasetPtr open_mosaic(const std::vector<std::string>& files) {
  const OGRSpatialReference* first_srs = nullptr;
  DatasetPtr first;
  double first_gt[6] = {};
  for (std::size_t t = 0; t < files.size(); ++t) {
    DatasetPtr ds = open_raster(files[t]);
    double gt[6];
    if (ds->GetGeoTransform(gt) != CE_None)
      throw DemError("mosaic tile '" + files[t] + "' has no geotransform, so it cannot be placed");
    check_north_up(files[t], gt);
    if (t == 0) {
      std::copy(gt, gt + 6, first_gt);
      first = std::move(ds);
      first_srs = first->GetSpatialRef();
      continue;
    }
    if (ds->GetRasterCount() != first->GetRasterCount())
      throw DemError("mosaic tiles differ in band count: '" + files[0] + "' has " +
                     std::to_string(first->GetRasterCount()) + ", '" + files[t] + "' has " +
                     std::to_string(ds->GetRasterCount()));
    const OGRSpatialReference* srs = ds->GetSpatialRef();
    const bool same_crs = (!srs && !first_srs) || (srs && first_srs && srs->IsSame(first_srs));
    if (!same_crs)
      throw DemError("mosaic tiles have different CRSs ('" + files[0] + "' vs '" + files[t] +
                     "'); reproject them to one CRS first");
    const double rel = 1e-6;
    if (std::abs(gt[1] - first_gt[1]) > rel * std::abs(first_gt[1]) ||
        std::abs(gt[5] - first_gt[5]) > rel * std::abs(first_gt[5]))
      throw DemError("mosaic tiles have different pixel sizes ('" + files[0] + "': " + fmt(first_gt[1]) +
                     ", '" + files[t] + "': " + fmt(gt[1]) + "); resample them to one grid first");
  }
  std::vector<const char*> names;
  for (const auto& f : files) names.push_back(f.c_str());
  names.push_back(nullptr);
  GdalErrorCapture capture;
  // An alpha band built from the tiles' masks marks both their voids and the gaps
  // between tiles, which would otherwise read as height 0 when tiles lack nodata.
  char* vrt_args[] = {const_cast<char*>("-addalpha"), nullptr};
  GDALBuildVRTOptions* opts = GDALBuildVRTOptionsNew(vrt_args, nullptr);
  int usage_error = 0;
  GDALDatasetH vrt = GDALBuildVRT("", static_cast<int>(files.size()), nullptr, names.data(), opts,
                                  &usage_error);
  GDALBuildVRTOptionsFree(opts);
  if (!vrt || usage_error)
    throw DemError("cannot mosaic " + std::to_string(files.size()) + " tiles: " + capture.failure());
  return DatasetPtr(GDALDataset::FromHandle(vrt));
}

DatasetPtr open_inputs(const std::vector<std::string>& files) {
  return files.size() == 1 ? open_raster(files[0]) : open_mosaic(files);
}

// Metres per stored vertical unit: the band's unit type, else the vertical CRS' unit.
double vertical_unit_factor(GDALRasterBand& band, const OGRSpatialReference* srs, std::string& unit,
                            std::vector<std::string>& warnings) {
  unit = band.GetUnitType() ? band.GetUnitType() : "";
  const std::string u = lower(unit);
  if (u.empty() || u == "m" || u == "metre" || u == "meter" || u == "metres" || u == "meters") {
    if (u.empty() && srs && srs->IsCompound()) {
      const char* name = nullptr;
      const double f = srs->GetTargetLinearUnits("VERT_CS", &name);
      if (f > 0 && std::isfinite(f)) {
        unit = name ? name : "metre";
        return f;
      }
    }
    if (unit.empty()) unit = "metre";
    return 1.0;
  }
  if (u == "ft" || u == "foot" || u == "feet" || u == "international foot" || u == "foot (international)")
    return 0.3048;
  if (u == "us-ft" || u == "us survey foot" || u == "us_survey_foot" || u == "foot_us" || u == "ftus" ||
      u == "us foot" || u == "survey foot")
    return 1200.0 / 3937.0;
  if (u == "cm" || u == "centimetre" || u == "centimeter") return 0.01;
  if (u == "dm" || u == "decimetre" || u == "decimeter") return 0.1;
  if (u == "km" || u == "kilometre" || u == "kilometer") return 1000.0;
  warnings.push_back("unknown vertical unit '" + unit + "'; heights are taken as metres");
  return 1.0;
}

GeoReference read_georef(GDALDataset& ds) {
  GeoReference g;
  double gt[6];
  if (ds.GetGeoTransform(gt) == CE_None) {
    std::copy(gt, gt + 6, g.geotransform.begin());
  } else {
    g.has_geotransform = false;
    g.geotransform = {0, 1, 0, 0, 0, -1};
  }
  if (const OGRSpatialReference* srs = ds.GetSpatialRef(); srs && !srs->IsEmpty()) {
    char* wkt = nullptr;
    const char* wkt_opts[] = {"FORMAT=WKT2_2019", nullptr};
    if (srs->exportToWkt(&wkt, wkt_opts) == OGRERR_NONE && wkt) g.crs_wkt = wkt;
    CPLFree(wkt);
    g.geographic = srs->IsGeographic();
  }
  return g;
}

DemInfo info_of(GDALDataset& ds, std::vector<std::string> files) {
  DemInfo info;
  info.width = ds.GetRasterXSize();
  info.height = ds.GetRasterYSize();
  info.bands = ds.GetRasterCount();
  info.georef = read_georef(ds);
  if (info.bands > 0) {
    int has = 0;
    const double nd = ds.GetRasterBand(1)->GetNoDataValue(&has);
    if (has) info.nodata = nd;
  }
  info.files = std::move(files);
  return info;
}

// Mirror the rows (south-up rasters) or columns (east-to-west) so row 0 is north and
// columns grow east, adjusting the geotransform to describe the same footprint.
void make_north_up(HeightField& f) {
  auto& gt = f.georef.geotransform;
  const int w = f.width, h = f.height;
  if (gt[5] > 0) {
    for (int j = 0; j < h / 2; ++j)
      for (int i = 0; i < w; ++i) {
        std::swap(f.heights[static_cast<std::size_t>(j) * w + i], f.heights[static_cast<std::size_t>(h - 1 - j) * w + i]);
        std::swap(f.valid[static_cast<std::size_t>(j) * w + i], f.valid[static_cast<std::size_t>(h - 1 - j) * w + i]);
      }
    gt[3] += gt[5] * h;
    gt[5] = -gt[5];
  }
  if (gt[1] < 0) {
    for (int j = 0; j < h; ++j) {
      std::reverse(f.heights.begin() + static_cast<std::ptrdiff_t>(j) * w, f.heights.begin() + static_cast<std::ptrdiff_t>(j + 1) * w);
      std::reverse(f.valid.begin() + static_cast<std::ptrdiff_t>(j) * w, f.valid.begin() + static_cast<std::ptrdiff_t>(j + 1) * w);
    }
    gt[0] += gt[1] * w;
    gt[1] = -gt[1];
  }
}

// The band's nodata value, or options.nodata over it.
std::optional<double> declared_nodata(GDALRasterBand& band, const DemReadOptions& options) {
  if (options.nodata) return options.nodata;
  int has = 0;
  const double value = band.GetNoDataValue(&has);
  return has ? std::optional<double>(value) : std::nullopt;
}

DemError no_valid_height(const std::string& name) {
  return DemError("'" + name + "' holds no valid height: every pixel is nodata");
}

std::string stray_nan_warning(std::size_t count, const std::string& name) {
  return std::to_string(count) + " NaN pixel(s) in '" + name + "' are not the declared nodata value; treated as nodata";
}

// How read_dataset finishes: read_dem fills the voids and warns of stray NaN itself;
// a strip of a larger read leaves both to its caller.
struct ReadControl {
  bool fill = true;
  std::size_t* stray_nan = nullptr;  // non-null: add the count here instead of warning
};

DemReadResult read_dataset(GDALDataset& ds, const std::string& name, const DemReadOptions& options,
                           const ReadControl& control = {}) {
  DemReadResult result;
  if (!(std::isfinite(options.z_factor) && options.z_factor > 0))
    throw DemError("invalid z factor " + fmt(options.z_factor) + ": must be a positive number");
  if (!(options.min_plausible_m < options.max_plausible_m))
    throw DemError("invalid plausible height range");
  const int W = ds.GetRasterXSize(), H = ds.GetRasterYSize();
  result.source_width = W;
  result.source_height = H;
  int bands = ds.GetRasterCount();
  // A trailing alpha band (ours on mosaics, or an RGBA-style file) holds no heights.
  if (bands > 1 && ds.GetRasterBand(bands)->GetColorInterpretation() == GCI_AlphaBand) --bands;
  if (bands < 1) throw DemError("'" + name + "' has no raster band");
  if (options.band < 1 || options.band > bands)
    throw DemError("'" + name + "' has " + std::to_string(bands) + " band(s); band " +
                   std::to_string(options.band) + " does not exist");
  PixelRect win{0, 0, W, H};
  if (options.window) {
    win = *options.window;
    if (win.empty() || win.x0 < 0 || win.y0 < 0 || win.x1() > W || win.y1() > H)
      throw DemError("window " + std::to_string(win.width) + "×" + std::to_string(win.height) + " at (" +
                     std::to_string(win.x0) + ", " + std::to_string(win.y0) + ") is not inside '" + name +
                     "' (" + std::to_string(W) + "×" + std::to_string(H) + ")");
  }
  if (win.width < 2 || win.height < 2)
    throw DemError("'" + name + "' is " + std::to_string(win.width) + "×" + std::to_string(win.height) +
                   " pixels; a DEM needs at least 2×2");

  HeightField& f = result.field;
  f.width = win.width;
  f.height = win.height;
  f.origin_column = win.x0;
  f.origin_row = win.y0;
  f.georef = read_georef(ds);
  check_north_up(name, f.georef.geotransform.data());
  auto& gt = f.georef.geotransform;
  gt[0] += win.x0 * gt[1];
  gt[3] += win.y0 * gt[5];

  GDALRasterBand& band = *ds.GetRasterBand(options.band);
  const std::optional<double> nodata = declared_nodata(band, options);
  int has_scale = 0, has_offset = 0;
  const double scale = band.GetScale(&has_scale);
  const double offset = band.GetOffset(&has_offset);
  const double unit_m = vertical_unit_factor(band, ds.GetSpatialRef(), result.vertical_unit, result.warnings);
  const double value_scale = (has_scale ? scale : 1.0) * unit_m;
  const double value_offset = (has_offset ? offset : 0.0) * unit_m;
  const bool is_float32 = band.GetRasterDataType() == GDT_Float32;
  // Use the GDAL mask unless it only encodes the nodata value we compare against anyway.
  const int mask_flags = band.GetMaskFlags();
  const bool use_mask = !(mask_flags & GMF_ALL_VALID) && !(mask_flags == GMF_NODATA);
  const bool nodata_is_nan = nodata && std::isnan(*nodata);

  const std::size_t n = static_cast<std::size_t>(f.width) * f.height;
  f.heights.resize(n);
  f.valid.assign(n, 1);
  std::size_t stray_nan = 0;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  // Read in strips of ≤ 64 Ki values (512 KiB of doubles, reused) so no raster needs
  // a double-precision copy in memory: fresh memory costs ≈ 3 ms per MiB to touch on
  // the CI VM.
  const int strip = std::max(1, static_cast<int>(std::min<std::size_t>(1u << 16, n) / f.width));
  std::vector<double> raw;
  std::vector<std::uint8_t> mask;
  GdalErrorCapture capture;
  for (int j0 = 0; j0 < f.height; j0 += strip) {
    const int rows = std::min(strip, f.height - j0);
    raw.resize(static_cast<std::size_t>(rows) * f.width);
    if (band.RasterIO(GF_Read, win.x0, win.y0 + j0, f.width, rows, raw.data(), f.width, rows, GDT_Float64, 0,
                      0, nullptr) != CE_None)
      throw DemError("cannot read '" + name + "' (rows " + std::to_string(win.y0 + j0) + "…): " +
                     capture.failure("read error; the file may be truncated or corrupt"));
    if (use_mask) {
      mask.resize(raw.size());
      if (band.GetMaskBand()->RasterIO(GF_Read, win.x0, win.y0 + j0, f.width, rows, mask.data(), f.width, rows,
                                       GDT_Byte, 0, 0, nullptr) != CE_None)
        throw DemError("cannot read the nodata mask of '" + name + "': " + capture.failure());
    }
    for (int r = 0; r < rows; ++r)
      for (int i = 0; i < f.width; ++i) {
        const std::size_t s = static_cast<std::size_t>(r) * f.width + i;
        const std::size_t k = static_cast<std::size_t>(j0 + r) * f.width + i;
        const double v = raw[s];
        bool ok = !(use_mask && mask[s] == 0);
        if (nodata && ok && !nodata_is_nan)
          ok = is_float32 ? static_cast<float>(v) != static_cast<float>(*nodata) : v != *nodata;
        if (ok && std::isnan(v)) {
          ok = false;
          if (!nodata_is_nan) ++stray_nan;
        }
        if (!ok) {
          f.valid[k] = 0;
          f.heights[k] = 0.0f;
          continue;
        }
        if (std::isinf(v))
          throw DemError("'" + name + "' holds an infinite height at pixel (" + std::to_string(win.x0 + i) +
                         ", " + std::to_string(win.y0 + j0 + r) + ")");
        const double m = v * value_scale + value_offset;
        if (m < options.min_plausible_m || m > options.max_plausible_m)
          throw DemError("'" + name + "' holds an implausible height " + fmt(m) + " m at pixel (" +
                         std::to_string(win.x0 + i) + ", " + std::to_string(win.y0 + j0 + r) +
                         "), outside " + fmt(options.min_plausible_m) + "…" + fmt(options.max_plausible_m) +
                         " m; is its nodata value set or its vertical unit wrong?");
        const double z = m * options.z_factor;
        lo = std::min(lo, z);
        hi = std::max(hi, z);
        f.heights[k] = static_cast<float>(z);
      }
  }
  for (const auto& w : capture.warnings()) result.warnings.push_back("GDAL: " + w);
  if (control.stray_nan) *control.stray_nan += stray_nan;
  else if (stray_nan > 0)
    result.warnings.push_back(stray_nan_warning(stray_nan, name));

  result.nodata_count = static_cast<std::size_t>(std::count(f.valid.begin(), f.valid.end(), 0));
  const bool all_nodata = result.nodata_count == n;
  if (all_nodata && !options.allow_all_nodata) throw no_valid_height(name);
  result.min_height = all_nodata ? 0.0 : lo;
  result.max_height = all_nodata ? 0.0 : hi;

  make_north_up(f);
  // Voids only (most DEMs have none: no fill's copies and queues of the whole grid).
  if (control.fill && result.nodata_count > 0 && !all_nodata) fill_voids(f, options.fill);
  f.nodata = nodata_for_outputs(nodata, result.nodata_count > 0);

  MetricSpacing sp = metric_spacing(f.georef, f.height, options, result.warnings);
  f.dy = sp.dy;
  f.dx_per_row = std::move(sp.dx_per_row);
  f.revision = 0;
  f.last_dirty = f.bounds();
  return result;
}

}  // namespace

void fill_voids(HeightField& f, VoidFill fill) {
  const std::size_t n = static_cast<std::size_t>(f.width) * f.height;
  if (f.width < 1 || f.height < 1 || f.heights.size() != n || f.valid.size() != n)
    throw DemError("fill_voids: heights and mask do not match the grid size");
  float lo = std::numeric_limits<float>::infinity();
  for (std::size_t k = 0; k < n; ++k)
    if (f.valid[k]) lo = std::min(lo, f.heights[k]);
  if (!std::isfinite(lo)) throw DemError("fill_voids: no valid height to fill from");
  switch (fill) {
    case VoidFill::Laplace: fill_laplace(f.heights, f.valid, f.width, f.height); break;
    case VoidFill::Nearest: fill_nearest(f.heights, f.valid, f.width, f.height); break;
    case VoidFill::Minimum: fill_constant(f.heights, f.valid, lo); break;
  }
}

DemReadResult read_dem(const std::vector<std::string>& paths, const DemReadOptions& options) {
  detail::ensure_gdal_registered();
  const std::vector<std::string> files = expand_inputs(paths);
  DatasetPtr ds = open_inputs(files);
  const std::string name = files.size() == 1 ? files[0] : "mosaic of " + std::to_string(files.size()) + " tiles";
  return read_dataset(*ds, name, options);
}

DemReadResult read_dem(const std::string& path, const DemReadOptions& options) {
  return read_dem(std::vector<std::string>{path}, options);
}

DemReadResult read_dem_in_strips(const std::vector<std::string>& paths, const DemReadOptions& options, int rows,
                                 const std::function<void(const HeightField& strip, int first_row)>& sink) {
  if (options.window) throw DemError("a DEM read in strips cannot also be read in a window");
  detail::ensure_gdal_registered();
  const std::vector<std::string> files = expand_inputs(paths);
  DatasetPtr ds = open_inputs(files);
  const std::string name = files.size() == 1 ? files[0] : "mosaic of " + std::to_string(files.size()) + " tiles";
  const int W = ds->GetRasterXSize(), H = ds->GetRasterYSize();
  DemReadOptions strip_options = options;
  strip_options.allow_all_nodata = true;
  std::size_t stray_nan = 0;
  const ReadControl control{false, &stray_nan};
  DemReadResult result;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  rows = std::max(rows, 2);  // the reader's minimum
  // A south-up file's strips come south first, each turned north up.
  double file_gt[6];
  const bool south_up = ds->GetGeoTransform(file_gt) == CE_None && file_gt[5] > 0;
  for (int y0 = 0; y0 < H;) {
    int n = std::min(rows, H - y0);
    if (H - y0 - n == 1) ++n;  // no last strip of one row
    strip_options.window = PixelRect{0, y0, W, n};
    DemReadResult strip = read_dataset(*ds, name, strip_options, control);
    for (auto& w : strip.warnings)
      if (std::find(result.warnings.begin(), result.warnings.end(), w) == result.warnings.end())
        result.warnings.push_back(std::move(w));
    const int first_row = south_up ? H - y0 - n : y0;
    if (y0 == 0) {
      result.field.georef = strip.field.georef;
      result.field.georef.geotransform[3] -= first_row * result.field.georef.geotransform[5];
      result.vertical_unit = strip.vertical_unit;
    }
    result.nodata_count += strip.nodata_count;
    if (strip.nodata_count < strip.field.size()) {
      lo = std::min(lo, strip.min_height);
      hi = std::max(hi, strip.max_height);
    }
    sink(strip.field, first_row);
    y0 += n;
  }
  if (stray_nan > 0) result.warnings.push_back(stray_nan_warning(stray_nan, name));
  const std::size_t total = static_cast<std::size_t>(W) * H;
  if (result.nodata_count == total && !options.allow_all_nodata) throw no_valid_height(name);
  result.min_height = result.nodata_count == total ? 0.0 : lo;
  result.max_height = result.nodata_count == total ? 0.0 : hi;
  result.source_width = W;
  result.source_height = H;
  HeightField& f = result.field;
  f.width = W;
  f.height = H;
  f.nodata = nodata_for_outputs(declared_nodata(*ds->GetRasterBand(options.band), options), result.nodata_count > 0);
  std::vector<std::string> spacing_warnings;  // the strips gave them already
  MetricSpacing sp = metric_spacing(f.georef, H, options, spacing_warnings);
  f.dy = sp.dy;
  f.dx_per_row = std::move(sp.dx_per_row);
  f.last_dirty = f.bounds();
  return result;
}

DemInfo inspect_dem(const std::vector<std::string>& paths) {
  detail::ensure_gdal_registered();
  std::vector<std::string> files = expand_inputs(paths);
  DatasetPtr ds = open_inputs(files);
  DemInfo info = info_of(*ds, files);
  if (files.size() > 1) info.bands -= 1;  // the mosaic's alpha band is ours, not the data's
  info.files = std::move(files);
  return info;
}

std::optional<double> nodata_for_outputs(std::optional<double> declared, bool voids) {
  return declared ? declared : (voids ? std::optional<double>(-32768.0) : std::nullopt);
}

void cap_gdal_cache_for_streaming() {
  constexpr long long kStreamingCacheBytes = 256LL << 20;
  if (!CPLGetConfigOption("GDAL_CACHEMAX", nullptr)) GDALSetCacheMax64(kStreamingCacheBytes);
}

DemInfo inspect_dem(const std::string& path) { return inspect_dem(std::vector<std::string>{path}); }

}  // namespace skylit::terrain
