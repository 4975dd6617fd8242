#include "flight/lon_lat_projection.h"

#include <ogr_spatialref.h>

#include <stdexcept>

namespace skylit::flight {

LonLatToCrs::LonLatToCrs(const std::string& crs_wkt) {
  if (crs_wkt.empty()) throw std::invalid_argument("the DEM has no CRS: a track cannot be placed on it");
  OGRSpatialReference wgs84, target;
  wgs84.SetWellKnownGeogCS("WGS84");
  wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  if (target.importFromWkt(crs_wkt.c_str()) != OGRERR_NONE) throw std::invalid_argument("the DEM's CRS cannot be parsed");
  target.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  transform_.reset(OGRCreateCoordinateTransformation(&wgs84, &target));
  if (!transform_) throw std::invalid_argument("GDAL cannot transform WGS 84 longitude/latitude to the DEM's CRS");
}

LonLatToCrs::~LonLatToCrs() = default;
LonLatToCrs::LonLatToCrs(LonLatToCrs&&) noexcept = default;

glm::dvec2 LonLatToCrs::operator()(double lon_deg, double lat_deg) const {
  double x = lon_deg, y = lat_deg;
  if (!transform_->Transform(1, &x, &y))
    throw std::runtime_error("cannot transform lon " + std::to_string(lon_deg) + ", lat " + std::to_string(lat_deg) +
                             " to the DEM's CRS");
  return {x, y};
}

}  // namespace skylit::flight
