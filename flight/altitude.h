// The height of a fix in the DEM's vertical datum. DEMs are taken to be heights above the
// EGM96 geoid (mean sea level; SRTM's datum), so:
//  * gnss (the default): the GNSS channel (ellipsoidal → MSL through flight/geoid.h; MSL
//    as is), else the format's stated altitude (MSL as is; above_ground on the ground
//    height); no height when the fix has neither.
//  * pressure (only on request): ISA pressure altitude taken as MSL height. It is the
//    height in the standard atmosphere, equal to MSL only at 1013.25 hPa and 15 °C at
//    sea level; a day's QNH and temperature move it by tens to hundreds of metres.
//  * agl_offset: a fixed height above the ground under the aircraft (tracks without a
//    usable altitude, ground vehicles, or for a view from a known height).
// The ground height comes from a callback, so this library needs no DEM sampler.
#pragma once

#include <functional>
#include <memory>
#include <optional>

#include "flight/geoid.h"
#include "flight/track.h"

namespace skylit::flight {

enum class AltitudeSource { gnss, pressure, agl_offset };

struct AltitudeMode {
  AltitudeSource source = AltitudeSource::gnss;
  double agl_offset_m = 0.0;  // agl_offset only
};

// DEM height (its vertical datum) at a position (x east, y north) in the DEM's CRS;
// NaN where the DEM has none.
using GroundHeight = std::function<double(double x, double y)>;

class AltitudeResolver {
 public:
  // Throws std::invalid_argument when the mode needs a ground height and none is given.
  explicit AltitudeResolver(AltitudeMode mode, GroundHeight ground = {});

  // The fix's height in the DEM datum, or nullopt when the fix has no altitude the mode
  // can use (or the ground is unknown there). x, y: the fix in the DEM's CRS.
  std::optional<double> height(const Fix& fix, double x, double y) const;

  // True when some fix of the track has an altitude this mode can use (agl_offset: always).
  bool usable(const Track& track) const;

 private:
  std::optional<double> from(const Altitude& a, const Fix& fix, double x, double y) const;
  AltitudeMode mode_;
  GroundHeight ground_;
  mutable std::unique_ptr<EllipsoidToGeoid> geoid_;  // made on first ellipsoidal height
};

}  // namespace skylit::flight
