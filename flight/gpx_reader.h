// GPX 1.0/1.1 tracks (topografix.com/GPX/1/1): trk/trkseg/trkpt with lat/lon
// attributes, <ele> and <time>.
//
// Policy (tests rely on it):
//  * One Track per <trk> (its segments joined; the gap between them is a time gap);
//    id = the trk's <name>.
//  * <ele> is metres above mean sea level: the schema defines <geoidheight> as the
//    "height of geoid (mean sea level) above WGS84 earth ellipsoid, as defined in NMEA
//    GGA", the NMEA GGA altitude being above the geoid; ele goes to Fix::stated, geoid_msl.
//  * <time> is ISO 8601 with Z, an offset or fractional seconds; a trkpt without a time
//    cannot be placed in time: error naming the line. Speed (GPX 1.0 <speed>,
//    <course>) is kept when present.
#pragma once

#include <istream>
#include <string>
#include <vector>

#include "flight/track.h"

namespace skylit::flight {

std::vector<Track> read_gpx(std::istream& in, const std::string& name);

}  // namespace skylit::flight
