// A flight track as data: timed fixes in WGS 84 with every altitude channel the file
// holds, each kept with its datum (DESIGN.md "Aircraft"; shared/notes/user-expectations.md:
// "keep pressure, GNSS (ellipsoid) and MSL altitudes as separate channels").
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace skylit::flight {

// What an altitude in metres is measured from.
enum class AltitudeDatum {
  wgs84_ellipsoid,  // GNSS height above the WGS 84 ellipsoid (IGC B record, OpenSky geoaltitude)
  geoid_msl,        // above mean sea level, the EGM96 geoid (GPX ele, KML absolute, IGC HFALG:GEO)
  pressure_isa,     // pressure altitude, ICAO standard atmosphere at 1013.25 hPa (IGC, OpenSky baro)
  above_ground,     // above the terrain under the aircraft (KML relativeToGround/clampToGround)
};

// "wgs84-ellipsoid", "egm96-msl", "pressure-isa", "above-ground".
const char* datum_name(AltitudeDatum datum);

struct Altitude {
  double metres = 0.0;
  AltitudeDatum datum = AltitudeDatum::geoid_msl;
};

// One I-record extension of an IGC B record (FXA, SIU, ENL, TAS, ...): its three-letter
// code and the raw characters at its byte range.
struct FixExtension {
  std::string code;
  std::string value;
};

struct Fix {
  double time_s = 0.0;  // UTC, seconds since 1970-01-01T00:00:00Z
  double lat_deg = 0.0;  // WGS 84
  double lon_deg = 0.0;
  std::optional<Altitude> gnss;      // satellite altitude (ellipsoid or MSL, as the file says)
  std::optional<Altitude> pressure;  // barometric altitude (ISA)
  std::optional<Altitude> stated;    // the format's own altitude of unknown sensor (GPX ele, KML, CSV alt)
  // IGC A (3-D fix) or V (2-D or no GNSS fix). Invalid fixes stay on the timeline but
  // are never used to place the aircraft.
  bool valid = true;
  std::optional<double> ground_speed_mps;   // as the file reports them (CSV)
  std::optional<double> track_deg;          // course over ground, clockwise from true north
  std::optional<double> vertical_rate_mps;  // positive climbing
  std::vector<FixExtension> extensions;
};

enum class TrackFormat { igc, gpx, kml, csv };
const char* format_name(TrackFormat format);  // "igc", "gpx", "kml", "csv"

struct Track {
  std::string id;        // glider id (IGC), ICAO 24-bit address (OpenSky) or the track's name
  std::string callsign;  // OpenSky's callsign, when the file has one
  TrackFormat format = TrackFormat::igc;
  std::vector<Fix> fixes;  // strictly increasing time
};

}  // namespace skylit::flight
