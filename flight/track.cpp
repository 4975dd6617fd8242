#include "flight/track.h"

namespace skylit::flight {

const char* datum_name(AltitudeDatum datum) {
  switch (datum) {
    case AltitudeDatum::wgs84_ellipsoid: return "wgs84-ellipsoid";
    case AltitudeDatum::geoid_msl: return "egm96-msl";
    case AltitudeDatum::pressure_isa: return "pressure-isa";
    case AltitudeDatum::above_ground: return "above-ground";
  }
  return "unknown";
}

const char* format_name(TrackFormat format) {
  switch (format) {
    case TrackFormat::igc: return "igc";
    case TrackFormat::gpx: return "gpx";
    case TrackFormat::kml: return "kml";
    case TrackFormat::csv: return "csv";
  }
  return "unknown";
}

}  // namespace skylit::flight
