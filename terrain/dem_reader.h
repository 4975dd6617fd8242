// Reading DEMs through GDAL into a HeightField: one raster, or many tiles mosaicked
// through an in-memory VRT; heights in metres, nodata filled for marching, metric
// spacing from the CRS (ellipsoidal arcs for geographic CRSs).
//
// Policy decisions (tests rely on them):
//  * Heights: value · band scale + band offset, then vertical unit → metres (band unit
//    type "ft"/"foot"/"US survey foot", or the vertical CRS' unit), then · z_factor.
//    The plausibility check (−12 km … 10 km) is made before z_factor.
//  * Nodata: pixels equal to the band nodata value (or options.nodata), pixels masked
//    by the band's mask, and NaN pixels are nodata: valid = 0, height filled
//    (options.fill) so that marching sees a continuous surface; outputs write nodata.
//    NaN that is not the declared nodata value adds a warning. ±Inf is an error.
//    field.nodata is the file's (or options.nodata) value; if voids exist without one
//    (NaN, mask, mosaic gaps) it is −32768. Mosaics mark gaps between tiles as voids.
//  * Spacing: options.xscale/yscale/scale (gdaldem -s: metres per map unit) win; else a
//    projected CRS uses its linear unit (feet → metres); a geographic CRS gets
//    dx_per_row[j] = parallel arc of one pixel at row j's centre latitude and
//    dy = meridian arc of the whole extent / rows, on the CRS' ellipsoid.
//  * No CRS (or no geotransform): error unless a scale is given; then a warning.
//  * Rotated/sheared geotransforms, rasters under 2×2, all-nodata rasters: errors.
//  * PixelIsPoint: GDAL already reports a corner-based geotransform; it is kept as is.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "terrain/height_field.h"

namespace skylit::terrain {

// Every reader failure; what() is one line naming the file and the problem. option():
// the DemReadOptions member that would fix it ("scale"), or empty; library messages
// name no command-line flag, a front end adds its own for option().
class DemError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
  DemError(const std::string& what, std::string option) : std::runtime_error(what), option_(std::move(option)) {}
  const std::string& option() const { return option_; }

 private:
  std::string option_;
};

enum class VoidFill {
  Laplace,  // smooth membrane: coarse-to-fine push–pull, then Gauss–Seidel relaxation
  Nearest,  // height of the nearest valid pixel (8-neighbour BFS distance)
  Minimum,  // lowest valid height of the raster: voids never cast shadows
};

struct DemReadOptions {
  int band = 1;                         // 1-based band index
  std::optional<double> scale;          // gdaldem -s: metres per horizontal map unit (both axes)
  std::optional<double> xscale;         // metres per map unit east–west (wins over scale)
  std::optional<double> yscale;         // metres per map unit north–south (wins over scale)
  double z_factor = 1.0;                // vertical exaggeration, multiplies heights (> 0)
  std::optional<double> nodata;         // overrides the band's nodata value
  VoidFill fill = VoidFill::Laplace;
  std::optional<PixelRect> window;      // read only this source window (tiled processing)
  // A raster (or window) with no valid height is returned with valid = 0 everywhere and
  // heights 0 instead of an error: a block of a large DEM may lie wholly in a void.
  bool allow_all_nodata = false;
  double min_plausible_m = -12000.0;    // valid heights outside [min, max] are an error
  double max_plausible_m = 10000.0;
};

struct DemReadResult {
  HeightField field;                    // heights (m, ·z_factor), valid mask, spacing, georef
  std::vector<std::string> warnings;    // one line each; the caller decides how to show them
  std::size_t nodata_count = 0;         // pixels with valid == 0
  double min_height = 0.0;              // over valid pixels, metres after z_factor
  double max_height = 0.0;
  std::string vertical_unit = "metre";  // unit the file stored heights in
  int source_width = 0, source_height = 0;  // full raster size before `window`
};

// Size and georeferencing of a DEM (or mosaic) without reading pixels.
struct DemInfo {
  int width = 0, height = 0, bands = 0;
  GeoReference georef;
  std::optional<double> nodata;
  std::vector<std::string> files;       // the rasters behind it (tiles of a mosaic)
};

// `path` may be a raster file, a directory (all rasters in it are mosaicked) or any
// GDAL dataset name (e.g. /vsizip/...). Throws DemError.
DemReadResult read_dem(const std::string& path, const DemReadOptions& options = {});
// Several tiles mosaicked into one grid (GDALBuildVRT; same CRS and band count required).
DemReadResult read_dem(const std::vector<std::string>& paths, const DemReadOptions& options = {});

// The DEM read a strip of rows at a time, for copies of DEMs too large to hold whole:
// each strip is read_dem of that window (the same heights, mask and checks) with its
// voids left unfilled (valid 0, height 0), handed to `sink` with its first row in the
// north-up DEM (a south-up file's strips come south first). Strips have `rows` rows,
// or one more where one row would be left. The result is read_dem's without pixels:
// `field` has the size, georef, spacing and nodata but no heights or mask; warnings,
// counts and the height range are the whole DEM's. options.window must be empty.
DemReadResult read_dem_in_strips(const std::vector<std::string>& paths, const DemReadOptions& options, int rows,
                                 const std::function<void(const HeightField& strip, int first_row)>& sink);

DemInfo inspect_dem(const std::string& path);
DemInfo inspect_dem(const std::vector<std::string>& paths);

// Fills the voids (valid == 0) of `field.heights` by `fill`, as the reader does; the
// mask is unchanged. Needs at least one valid texel (throws DemError otherwise).
void fill_voids(HeightField& field, VoidFill fill);

// The nodata value outputs write (policy above): the declared one, else −32768 where
// there are voids, else none.
std::optional<double> nodata_for_outputs(std::optional<double> declared, bool voids);

// Caps GDAL's block cache at 256 MiB unless GDAL_CACHEMAX is set, for runs that read a
// large DEM once (in blocks, or whole for tiles): GDAL's default, 5 % of RAM, would fill
// with blocks that are never read again and raise the peak memory by as much.
void cap_gdal_cache_for_streaming();

// Geographic DEMs reaching nearer a pole than this are refused with a clear error.
inline constexpr double kMaxGeographicLatitudeDeg = 89.0;

struct MetricSpacing {
  double dy = 1.0;                 // metres
  std::vector<double> dx_per_row;  // metres, one per row (row 0 = north)
};

// Metric spacing of a `rows`-row grid with this georeference, by the rules above
// (used by the reader; exposed for windows and tests). Adds warnings (no CRS with a
// user scale, high latitude); throws DemError when spacing cannot be determined.
MetricSpacing metric_spacing(const GeoReference& georef, int rows, const DemReadOptions& options,
                             std::vector<std::string>& warnings);

}  // namespace skylit::terrain
