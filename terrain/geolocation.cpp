#include "terrain/geolocation.h"

#include "terrain/dem_reader.h"
#include "terrain/gdal_util.h"

#include <ogr_spatialref.h>

#include <cmath>
#include <memory>
#include <string>

namespace skylit::terrain {

std::optional<LatLon> grid_centre_lat_lon(const GeoReference& georef, int width, int height) {
  const auto at = grid_points_lat_lon(georef, {{0.5 * width, 0.5 * height}});
  if (!at) return std::nullopt;
  return at->front();
}

std::optional<std::vector<LatLon>> grid_points_lat_lon(const GeoReference& georef, const std::vector<PixelPoint>& points) {
  if (georef.crs_wkt.empty() || !georef.has_geotransform) return std::nullopt;
  detail::ensure_gdal_registered();
  detail::GdalErrorCapture quiet;
  OGRSpatialReference src, wgs84;
  if (src.importFromWkt(georef.crs_wkt.c_str()) != OGRERR_NONE)
    throw DemError("cannot parse the DEM's CRS: " + quiet.failure("invalid WKT"));
  wgs84.SetWellKnownGeogCS("WGS84");
  // x = easting or longitude, y = northing or latitude, whatever the CRS' axis order.
  src.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  const std::unique_ptr<OGRCoordinateTransformation> to_wgs84(OGRCreateCoordinateTransformation(&src, &wgs84));
  if (!to_wgs84) throw DemError("cannot transform the DEM's CRS to WGS 84: " + quiet.failure("no transformation"));
  const auto& gt = georef.geotransform;
  std::vector<LatLon> out;
  out.reserve(points.size());
  for (const PixelPoint& p : points) {
    double x = gt[0] + p.column * gt[1] + p.row * gt[2];
    double y = gt[3] + p.column * gt[4] + p.row * gt[5];
    if (!to_wgs84->Transform(1, &x, &y) || !std::isfinite(x) || !std::isfinite(y))
      throw DemError("cannot transform the DEM's pixel (" + std::to_string(p.column) + ", " + std::to_string(p.row) +
                     ") to WGS 84: " + quiet.failure("point outside the CRS' area"));
    out.push_back({y, std::remainder(x, 360.0)});
  }
  return out;
}

}  // namespace skylit::terrain
