// WGS 84 longitude/latitude to a DEM's CRS (x east, y north in its units), through an
// OGR coordinate transformation with OAMS_TRADITIONAL_GIS_ORDER on both ends, so that
// EPSG:4326's official latitude-first axis order never swaps the coordinates.
#pragma once

#include <glm/vec2.hpp>

#include <memory>
#include <string>

class OGRCoordinateTransformation;

namespace skylit::flight {

class LonLatToCrs {
 public:
  // Throws std::invalid_argument when the WKT is empty or GDAL cannot build the transformation.
  explicit LonLatToCrs(const std::string& crs_wkt);
  ~LonLatToCrs();
  LonLatToCrs(LonLatToCrs&&) noexcept;

  // Throws std::runtime_error when the point cannot be transformed.
  glm::dvec2 operator()(double lon_deg, double lat_deg) const;

 private:
  std::unique_ptr<OGRCoordinateTransformation> transform_;
};

}  // namespace skylit::flight
