// Metric pixel spacing from the CRS: linear units for projected CRSs, ellipsoidal
// arcs (GeographicLib) for geographic ones, user scales first.
#include <GeographicLib/Ellipsoid.hpp>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "terrain/dem_reader.h"
#include "terrain/gdal_util.h"

namespace skylit::terrain {
namespace {

std::string fmt(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

void check_scale(const std::optional<double>& s, const char* name) {
  if (s && !(std::isfinite(*s) && *s > 0))
    throw DemError(std::string("invalid ") + name + " " + fmt(*s) + ": must be a positive number of metres per map unit");
}

// Spacing from the CRS alone.
MetricSpacing crs_spacing(const GeoReference& georef, int rows, std::vector<std::string>& warnings) {
  const auto& gt = georef.geotransform;
  const double px = std::abs(gt[1]), py = std::abs(gt[5]);
  MetricSpacing out;

  OGRSpatialReference srs;
  detail::ensure_gdal_registered();
  detail::GdalErrorCapture quiet;
  if (srs.importFromWkt(georef.crs_wkt.c_str()) != OGRERR_NONE)
    throw DemError("cannot parse the DEM's CRS: " + quiet.failure("invalid WKT"));
  srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  if (srs.IsGeocentric())
    throw DemError("the DEM's CRS is geocentric; a DEM needs a projected or geographic CRS");

  if (srs.IsGeographic()) {
    const double a = srs.GetSemiMajor();
    const double inv_f = srs.GetInvFlattening();
    const double f = inv_f > 0 ? 1.0 / inv_f : 0.0;  // 0: a sphere
    const double rad_per_unit = srs.GetAngularUnits();
    const double deg_per_unit = rad_per_unit * 180.0 / M_PI;
    const GeographicLib::Ellipsoid ell(a, f);
    const double lat_top = gt[3] * deg_per_unit;
    const double lat_bottom = (gt[3] + rows * gt[5]) * deg_per_unit;
    if (std::abs(lat_top) > 90.0 + 1e-9 || std::abs(lat_bottom) > 90.0 + 1e-9)
      throw DemError("geographic CRS but latitudes " + fmt(lat_top) + "…" + fmt(lat_bottom) +
                     " exceed ±90°; the geotransform is not in degrees");
    const double lat_max = std::min(90.0, std::max(std::abs(lat_top), std::abs(lat_bottom)));
    // Within a degree of a pole the rows' spacing falls toward 0 and rays cross the pole:
    // a grid of local east–west and north–south steps no longer describes the ground.
    if (lat_max > kMaxGeographicLatitudeDeg)
      throw DemError("the DEM reaches latitude " + fmt(lat_max) + "°, within " +
                     fmt(90.0 - kMaxGeographicLatitudeDeg) +
                     "° of the pole, where a geographic grid has no usable east–west spacing; reproject it "
                     "to a polar stereographic CRS first (gdalwarp -t_srs EPSG:3413 north, EPSG:3031 south)");
    // One pixel north–south: the meridian arc of the whole extent, shared evenly.
    out.dy = std::abs(ell.MeridianDistance(std::clamp(lat_top, -90.0, 90.0)) -
                      ell.MeridianDistance(std::clamp(lat_bottom, -90.0, 90.0))) / rows;
    out.dx_per_row.resize(rows);
    const double dlon = px * rad_per_unit;  // radians of longitude per pixel
    for (int j = 0; j < rows; ++j) {
      const double lat = (gt[3] + (j + 0.5) * gt[5]) * deg_per_unit;
      // Parallel arc: radius of the circle of latitude times the longitude step.
      out.dx_per_row[j] = std::max(ell.CircleRadius(lat) * dlon, 1e-3);
    }
    if (lat_max > 80.0)
      warnings.push_back("the DEM reaches latitude " + fmt(lat_max) +
                         "°: east–west pixel spacing shrinks strongly toward the pole");
    return out;
  }

  // Projected or local CRS: linear unit in metres (feet → 0.3048, US feet → 1200/3937).
  const char* unit_name = nullptr;
  const double m_per_unit = srs.GetLinearUnits(&unit_name);
  if (!(m_per_unit > 0 && std::isfinite(m_per_unit)))
    throw DemError("the DEM's CRS has no usable linear unit; give its scale (metres per map unit)", "scale");
  if (!srs.IsProjected())
    warnings.push_back(std::string("the DEM's CRS is neither projected nor geographic; using its linear unit '") +
                       (unit_name ? unit_name : "?") + "'");
  out.dy = py * m_per_unit;
  out.dx_per_row.assign(rows, px * m_per_unit);
  return out;
}

}  // namespace

MetricSpacing metric_spacing(const GeoReference& georef, int rows, const DemReadOptions& options,
                             std::vector<std::string>& warnings) {
  check_scale(options.scale, "scale");
  check_scale(options.xscale, "xscale");
  check_scale(options.yscale, "yscale");
  if (rows < 1) throw DemError("metric spacing: the grid has no rows");
  const auto& gt = georef.geotransform;
  if (gt[2] != 0.0 || gt[4] != 0.0)
    throw DemError("rotated or sheared geotransform (terms " + fmt(gt[2]) + ", " + fmt(gt[4]) +
                   ") is not supported; warp the DEM to a north-up grid first (gdalwarp)");
  const double px = std::abs(gt[1]), py = std::abs(gt[5]);
  if (!(px > 0 && py > 0 && std::isfinite(px) && std::isfinite(py)))
    throw DemError("invalid pixel size " + fmt(gt[1]) + " × " + fmt(gt[5]) + " in the geotransform");

  // The user's scales win over the CRS (gdaldem -s / --xscale / --yscale semantics).
  const std::optional<double> xs = options.xscale ? options.xscale : options.scale;
  const std::optional<double> ys = options.yscale ? options.yscale : options.scale;
  const bool unknown = georef.crs_wkt.empty() || !georef.has_geotransform;
  const std::string missing = georef.crs_wkt.empty() ? "CRS" : "geotransform";
  MetricSpacing out;
  if (xs && ys) {
    if (unknown)
      warnings.push_back("the DEM has no " + missing + "; metric spacing from the given scale (" +
                         fmt(px * *xs) + " m × " + fmt(py * *ys) + " m per pixel)");
    out.dy = py * *ys;
    out.dx_per_row.assign(rows, px * *xs);
    return out;
  }
  if (unknown)
    throw DemError("the DEM has no " + missing +
                       ", so its pixel size in metres is unknown; give its scale (metres per map unit, "
                       "e.g. 30 for a 30 m grid stored with unit pixels)",
                   "scale");
  out = crs_spacing(georef, rows, warnings);
  if (xs) out.dx_per_row.assign(rows, px * *xs);
  if (ys) out.dy = py * *ys;
  return out;
}

}  // namespace skylit::terrain
