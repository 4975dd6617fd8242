// OpenSky state vectors and plain time,lat,lon,alt CSV, read against the values written
// into the rows, with the datums of flight/csv_reader.h.
#include "flight/csv_reader.h"

#include <gtest/gtest.h>

#include <sstream>

namespace skylit::flight {
namespace {

std::vector<Track> csv(const std::string& text) {
  std::istringstream in(text);
  return read_csv(in, "f.csv");
}

std::string error_of(const std::string& text) {
  try {
    csv(text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(CsvReader, OpenSkyStateVectorsBecomeOneTrackPerAircraft) {
  const auto tracks = csv(
      "time,icao24,lat,lon,velocity,heading,vertrate,callsign,onground,alert,spi,squawk,baroaltitude,geoaltitude\n"
      "1782036000,3c6444,48.1,11.5,230.5,90.0,-5.2,DLH4AB  ,False,False,False,1000,10972.8,11049.0\n"
      "1782036000,4ca7b3,47.0,8.0,,,,,True,False,False,,,\n"
      "1782036010,3c6444,48.1,11.53,231.0,91.0,-5.0,DLH4AB  ,False,False,False,1000,10965.2,11041.4\n"
      "1782036010,4ca7b3,,,,,,,True,False,False,,,\n");
  ASSERT_EQ(tracks.size(), 2u);
  const Track& a = tracks[0];
  EXPECT_EQ(a.id, "3c6444");
  EXPECT_EQ(a.callsign, "DLH4AB");
  ASSERT_EQ(a.fixes.size(), 2u);
  const Fix& f = a.fixes[0];
  EXPECT_DOUBLE_EQ(f.time_s, 1782036000.0);
  EXPECT_DOUBLE_EQ(f.lat_deg, 48.1);
  EXPECT_DOUBLE_EQ(f.lon_deg, 11.5);
  EXPECT_DOUBLE_EQ(*f.ground_speed_mps, 230.5);
  EXPECT_DOUBLE_EQ(*f.track_deg, 90.0);
  EXPECT_DOUBLE_EQ(*f.vertical_rate_mps, -5.2);
  EXPECT_DOUBLE_EQ(f.pressure->metres, 10972.8);
  EXPECT_EQ(f.pressure->datum, AltitudeDatum::pressure_isa);
  EXPECT_DOUBLE_EQ(f.gnss->metres, 11049.0);
  EXPECT_EQ(f.gnss->datum, AltitudeDatum::wgs84_ellipsoid);
  EXPECT_EQ(tracks[1].id, "4ca7b3");
  ASSERT_EQ(tracks[1].fixes.size(), 1u);  // the row without a position is no fix
  EXPECT_FALSE(tracks[1].fixes[0].gnss);
}

TEST(CsvReader, PlainColumnsWithIsoTimesInAnyOrder) {
  const auto t = csv("Latitude, Longitude ,alt,time\r\n46.5,7.25,2400,2026-06-21T10:00:00Z\r\n46.6,7.3,2410,2026-06-21 10:00:01\r\n")[0];
  ASSERT_EQ(t.fixes.size(), 2u);
  EXPECT_DOUBLE_EQ(t.fixes[1].time_s, 1782036001.0);
  EXPECT_DOUBLE_EQ(t.fixes[1].lat_deg, 46.6);
  EXPECT_DOUBLE_EQ(t.fixes[1].stated->metres, 2410.0);
  EXPECT_EQ(t.fixes[1].stated->datum, AltitudeDatum::geoid_msl);
}

TEST(CsvReader, Errors) {
  EXPECT_EQ(error_of(""), "f.csv: empty file");
  EXPECT_NE(error_of("a,b,c\n1,2,3\n").find("f.csv:1: CSV header must name the columns time, lat and lon"), std::string::npos);
  EXPECT_EQ(error_of("time,lat,lon\n"), "f.csv: no track points (no rows with a time, lat and lon)");
  EXPECT_EQ(error_of("time,lat,lon\n10,1,2\n5,1,2\n"),
            "f.csv:3: time 1970-01-01T00:00:05Z runs backwards (previous fix at 1970-01-01T00:00:10Z)");
  EXPECT_NE(error_of("time,lat,lon\n10,1,200\n").find("f.csv:2: coordinates"), std::string::npos);
  EXPECT_EQ(error_of("time,lat,lon\n10,north,2\n"), "f.csv:2: lat 'north' is not a number");
  EXPECT_EQ(error_of("time,lat,lon\n1e300,1,2\n"), "f.csv:2: time 1e+300 s out of range (years 1900 to 2199)");
  EXPECT_EQ(error_of("time,lat,lon\nnoon,1,2\n"), "f.csv:2: time 'noon' is neither POSIX seconds nor ISO 8601");
}

}  // namespace
}  // namespace skylit::flight
