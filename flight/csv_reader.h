// Comma-separated tracks whose first line names the columns (any order, case-insensitive):
//  * OpenSky state vectors (opensky-network.org historical data / Impala exports):
//    time, icao24, lat, lon, velocity, heading, vertrate, callsign, onground,
//    baroaltitude, geoaltitude (other columns ignored). One Track per icao24.
//    velocity m/s, heading ° clockwise from true north, vertrate m/s. baroaltitude is
//    pressure altitude (Fix::pressure, ISA); geoaltitude, OpenSky's "geometric altitude in
//    meters", is the ADS-B GNSS height, which ADS-B (DO-260B) reports above the WGS 84
//    ellipsoid (HAE): Fix::gnss, wgs84_ellipsoid. Rows whose lat or lon is empty (OpenSky's
//    null: no position in that interval) carry no fix and are skipped.
//  * Plain time,lat,lon,alt: alt (or altitude, ele, elevation) in metres above mean sea
//    level: Fix::stated, geoid_msl.
// time is POSIX seconds (a number) or ISO 8601 (a time without a zone is UTC). Also
// accepted: timestamp for time, latitude/longitude for lat/lon, true_track for heading,
// vertical_rate for vertrate, baro_altitude/geo_altitude.
#pragma once

#include <istream>
#include <string>
#include <vector>

#include "flight/track.h"

namespace skylit::flight {

std::vector<Track> read_csv(std::istream& in, const std::string& name);

}  // namespace skylit::flight
