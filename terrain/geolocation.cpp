#include "terrain/geolocation.h"

#include "terrain/dem_reader.h"
#include "terrain/gdal_util.h"

#include <ogr_spatialref.h>

#include <cmath>
#include <memory>

namespace skylit::terrain {

std::optional<LatLon> grid_centre_lat_lon(const GeoReference& georef, int width, int height) {
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
  double x = gt[0] + 0.5 * width * gt[1] + 0.5 * height * gt[2];
  double y = gt[3] + 0.5 * width * gt[4] + 0.5 * height * gt[5];
  if (!to_wgs84->Transform(1, &x, &y) || !std::isfinite(x) || !std::isfinite(y))
    throw DemError("cannot transform the DEM's centre to WGS 84: " + quiet.failure("point outside the CRS' area"));
  return LatLon{y, std::remainder(x, 360.0)};
}

}  // namespace skylit::terrain
