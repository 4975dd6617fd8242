// Where a georeferenced grid lies on the Earth: the WGS 84 latitude and longitude of
// its centre, through its CRS (OGR coordinate transformation). The sun's position
// for a DEM (`skylit shade --time`) is computed there.
#pragma once

#include "terrain/height_field.h"

#include <optional>
#include <vector>

namespace skylit::terrain {

struct LatLon {
  double latitude_deg = 0.0;   // WGS 84, north positive
  double longitude_deg = 0.0;  // WGS 84, east positive, [−180, 180]
};

// Centre of a width × height grid (the middle of its pixel extent). nullopt when the
// georeference has no CRS or no geotransform; throws DemError when the CRS cannot be
// parsed or transformed to WGS 84.
std::optional<LatLon> grid_centre_lat_lon(const GeoReference& georef, int width, int height);

// The same for any points in pixel coordinates (column, row; pixel edges at integers,
// (0, 0) the top-left corner), through one transformation.
struct PixelPoint {
  double column = 0.0, row = 0.0;
};
std::optional<std::vector<LatLon>> grid_points_lat_lon(const GeoReference& georef, const std::vector<PixelPoint>& points);

}  // namespace skylit::terrain
