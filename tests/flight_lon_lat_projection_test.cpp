// WGS 84 lon/lat to a DEM's CRS: the synthetic scene's corner (UTM 32N 400000 E,
// 5200000 N) is at 46.94598832°N 7.68596912°E by `cs2cs EPSG:32632 EPSG:4326` (and by
// Krüger's series in scripts/make_sample_track.py); a geographic DEM keeps x = lon,
// y = lat whatever EPSG:4326's official axis order.
#include "flight/lon_lat_projection.h"

#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <stdexcept>

namespace skylit::flight {
namespace {

std::string wkt_of(int epsg) {
  OGRSpatialReference srs;
  EXPECT_EQ(srs.importFromEPSG(epsg), OGRERR_NONE);
  char* wkt = nullptr;
  srs.exportToWkt(&wkt);
  std::string s = wkt;
  CPLFree(wkt);
  return s;
}

TEST(LonLatToCrs, UtmCornerOfTheSyntheticScene) {
  const LonLatToCrs utm(wkt_of(32632));
  const glm::dvec2 p = utm(7.68596912, 46.94598832);
  EXPECT_NEAR(p.x, 400000.0, 0.01);
  EXPECT_NEAR(p.y, 5200000.0, 0.01);
}

TEST(LonLatToCrs, GeographicKeepsLonLatOrderAndBadCrsFails) {
  const LonLatToCrs geo(wkt_of(4326));
  const glm::dvec2 p = geo(7.5, 46.25);
  EXPECT_DOUBLE_EQ(p.x, 7.5);
  EXPECT_DOUBLE_EQ(p.y, 46.25);
  EXPECT_THROW(LonLatToCrs(""), std::invalid_argument);
  EXPECT_THROW(LonLatToCrs("not a crs"), std::invalid_argument);
}

}  // namespace
}  // namespace skylit::flight
