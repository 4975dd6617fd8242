// Ellipsoidal → MSL through PROJ checked against the EGM96 grid itself, read here by
// hand from its file (NOAA VDatum GTX layout: a big-endian header of south latitude,
// west longitude, latitude and longitude steps as doubles, rows and columns as int32,
// then float32 undulations row by row from the south): at a grid node PROJ's bilinear
// interpolation must return the node's value, between nodes the bilinear mean of four.
// (N(48°N, 11°E) = 45.96 m; `cs2cs EPSG:4979 EPSG:4326+5773` gives the same.)
#include "flight/altitude.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>

namespace skylit::flight {
namespace {

constexpr const char* kGrid = "/usr/share/proj/egm96_15.gtx";

template <class T>
T big_endian(std::ifstream& in) {
  unsigned char b[sizeof(T)];
  in.read(reinterpret_cast<char*>(b), sizeof b);
  if constexpr (std::endian::native == std::endian::little) std::reverse(b, b + sizeof b);
  T v;
  std::memcpy(&v, b, sizeof v);
  return v;
}

double grid_node(double lat, double lon) {
  std::ifstream in(kGrid, std::ios::binary);
  const double lat0 = big_endian<double>(in), lon0 = big_endian<double>(in);
  const double dlat = big_endian<double>(in), dlon = big_endian<double>(in);
  big_endian<std::int32_t>(in);  // rows
  const std::int32_t cols = big_endian<std::int32_t>(in);
  const long row = std::lround((lat - lat0) / dlat), col = std::lround((lon - lon0) / dlon);
  in.seekg(40 + 4 * (row * cols + col));
  return big_endian<float>(in);
}

TEST(EllipsoidToGeoid, MatchesTheEgm96GridNodesAndTheirBilinearMean) {
  if (!std::ifstream(kGrid)) GTEST_SKIP() << kGrid << " absent (proj-data)";
  const EllipsoidToGeoid geoid;
  const double n = grid_node(48.0, 11.0);
  EXPECT_NEAR(n, 45.96, 0.01);  // sanity of the hand reading
  EXPECT_NEAR(geoid.undulation(48.0, 11.0), n, 1e-3);
  EXPECT_NEAR(geoid.msl_height(48.0, 11.0, 2500.0), 2500.0 - n, 1e-3);
  const double mean = (grid_node(48.0, 11.0) + grid_node(48.0, 11.25) + grid_node(48.25, 11.0) + grid_node(48.25, 11.25)) / 4;
  EXPECT_NEAR(geoid.undulation(48.125, 11.125), mean, 1e-3);
  EXPECT_NEAR(geoid.undulation(-33.0, 151.25), grid_node(-33.0, 151.25), 1e-3);  // southern, eastern hemisphere
  EXPECT_NEAR(geoid.undulation(40.0, -105.0), grid_node(40.0, -105.0), 1e-3);    // western
}

TEST(AltitudeResolver, PicksTheChannelOfTheModeAndConvertsItsDatum) {
  if (!std::ifstream(kGrid)) GTEST_SKIP() << kGrid << " absent (proj-data)";
  Fix f;
  f.lat_deg = 48.0;
  f.lon_deg = 11.0;
  f.gnss = Altitude{2500.0, AltitudeDatum::wgs84_ellipsoid};
  f.pressure = Altitude{2420.0, AltitudeDatum::pressure_isa};
  const double n = grid_node(48.0, 11.0);
  EXPECT_NEAR(*AltitudeResolver({AltitudeSource::gnss}).height(f, 0, 0), 2500.0 - n, 1e-3);
  EXPECT_DOUBLE_EQ(*AltitudeResolver({AltitudeSource::pressure}).height(f, 0, 0), 2420.0);
  const GroundHeight ground = [](double x, double y) { return 1000.0 + x + 2 * y; };
  EXPECT_DOUBLE_EQ(*AltitudeResolver({AltitudeSource::agl_offset, 50.0}, ground).height(f, 3, 4), 1061.0);

  Fix kml;  // relativeToGround: on the ground height; without one, no height
  kml.stated = Altitude{120.0, AltitudeDatum::above_ground};
  EXPECT_DOUBLE_EQ(*AltitudeResolver({AltitudeSource::gnss}, ground).height(kml, 0, 0), 1120.0);
  EXPECT_FALSE(AltitudeResolver({AltitudeSource::gnss}).height(kml, 0, 0));
  EXPECT_FALSE(AltitudeResolver({AltitudeSource::pressure}).height(kml, 0, 0));
  EXPECT_THROW(AltitudeResolver({AltitudeSource::agl_offset, 10.0}), std::invalid_argument);
}

}  // namespace
}  // namespace skylit::flight
