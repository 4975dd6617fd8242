#include "flight/altitude.h"

#include <cmath>
#include <stdexcept>

namespace skylit::flight {

AltitudeResolver::AltitudeResolver(AltitudeMode mode, GroundHeight ground) : mode_(mode), ground_(std::move(ground)) {
  if (mode_.source == AltitudeSource::agl_offset && !ground_)
    throw std::invalid_argument("altitude agl-offset needs the ground height under the aircraft (a DEM)");
  if (!std::isfinite(mode_.agl_offset_m)) throw std::invalid_argument("altitude agl-offset must be a finite number of metres");
}

std::optional<double> AltitudeResolver::from(const Altitude& a, const Fix& fix, double x, double y) const {
  switch (a.datum) {
    case AltitudeDatum::geoid_msl:
    case AltitudeDatum::pressure_isa: return a.metres;
    case AltitudeDatum::wgs84_ellipsoid:
      if (!geoid_) geoid_ = std::make_unique<EllipsoidToGeoid>();
      return geoid_->msl_height(fix.lat_deg, fix.lon_deg, a.metres);
    case AltitudeDatum::above_ground: {
      if (!ground_) return std::nullopt;
      const double g = ground_(x, y);
      if (!std::isfinite(g)) return std::nullopt;
      return g + a.metres;
    }
  }
  return std::nullopt;
}

std::optional<double> AltitudeResolver::height(const Fix& fix, double x, double y) const {
  switch (mode_.source) {
    case AltitudeSource::gnss:
      if (fix.gnss) return from(*fix.gnss, fix, x, y);
      if (fix.stated) return from(*fix.stated, fix, x, y);
      return std::nullopt;
    case AltitudeSource::pressure:
      return fix.pressure ? from(*fix.pressure, fix, x, y) : std::nullopt;
    case AltitudeSource::agl_offset:
      return from(Altitude{mode_.agl_offset_m, AltitudeDatum::above_ground}, fix, x, y);
  }
  return std::nullopt;
}

bool AltitudeResolver::usable(const Track& track) const {
  for (const Fix& f : track.fixes) {
    switch (mode_.source) {
      case AltitudeSource::gnss:
        if (f.gnss || (f.stated && (f.stated->datum != AltitudeDatum::above_ground || ground_))) return true;
        break;
      case AltitudeSource::pressure:
        if (f.pressure) return true;
        break;
      case AltitudeSource::agl_offset: return true;
    }
  }
  return false;
}

}  // namespace skylit::flight
