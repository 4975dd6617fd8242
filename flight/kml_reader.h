// KML tracks with per-point times: <gx:Track> (KML 2.2 Google extension), its <when>
// elements paired in order with its <gx:coord> "lon lat alt" elements. GDAL's KML/LIBKML
// drivers drop the per-point times, so the XML is read directly.
//
// Policy (tests rely on it):
//  * One Track per gx:Track; id = the enclosing Placemark's <name>. A gx:MultiTrack's
//    tracks become separate tracks.
//  * altitudeMode (or gx:altitudeMode): absolute → the altitude is above mean sea level
//    (KML 2.2: "relative to sea level"), Fix::stated geoid_msl; relativeToGround →
//    Fix::stated above_ground; clampToGround (KML's default) → the altitude is ignored,
//    as KML ignores it, and the fix is on the ground: Fix::stated above_ground 0 m.
//    relativeToSeaFloor and clampToSeaFloor are rejected (no sea floor in a DEM).
//  * The numbers of <when> and <gx:coord> must match.
#pragma once

#include <istream>
#include <string>
#include <vector>

#include "flight/track.h"

namespace skylit::flight {

std::vector<Track> read_kml(std::istream& in, const std::string& name);

}  // namespace skylit::flight
