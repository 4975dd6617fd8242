// `skylit track FILE --dem DEM`: the terrain's light on each fix's aircraft. The sphere
// set is placed at the fix's pose (app/shade/tracked_aircraft.h); at the centroid of its
// spheres (volume-weighted) shading/point_visibility.h marches the sky and the sun, the
// sun at the fix's time and place (NREL SPA, apparent elevation, its azimuth taken in
// the grid as the renderer takes it).
#pragma once

#include "flight/altitude.h"
#include "flight/track.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace skylit::app::flight {

struct FixTerrain {
  bool inside_dem = false;
  bool below_ground = false;
  std::optional<double> ground_m;               // bilinear DEM height under the centroid
  std::optional<double> height_above_ground_m;  // the centroid's
  double height_m = 0.0;                        // the placed reference point's (DEM datum)
  double sun_azimuth_deg = 0.0, sun_elevation_deg = 0.0;
  double sun_horizon_deg = 0.0;  // the terrain's, or the sea-level horizon's beyond the DEM
  bool in_terrain_shadow = false;
  double sun_visible_fraction = 0.0;
  double sky_view = 1.0, sky_fraction = 1.0;
};

struct TrackTerrainSummary {
  std::size_t fixes = 0;      // with a result
  std::size_t over_dem = 0;   // of those, inside the DEM
  std::size_t in_shadow = 0;  // of those, in terrain shadow
  double sky_view_min = 1.0, sky_view_mean = 1.0;  // over those
};

class TrackTerrain {
 public:
  // Reads the DEM. Throws (one line) for a DEM that cannot be read or has no CRS, a bad
  // set, and tracks none of whose valid fixes lies over the DEM.
  TrackTerrain(const std::vector<skylit::flight::Track>& tracks, const std::string& track_file,
               const std::string& dem_path, const std::string& aircraft, const skylit::flight::AltitudeMode& altitude);

  // nullopt for invalid fixes and where the aircraft has no pose (a gap, no altitude).
  const std::optional<FixTerrain>& at(std::size_t track, std::size_t fix) const { return fixes_[track][fix]; }
  TrackTerrainSummary summary(std::size_t track) const;
  const std::string& dem() const { return dem_; }
  const std::string& aircraft() const { return aircraft_; }

 private:
  std::string dem_, aircraft_;
  std::vector<std::vector<std::optional<FixTerrain>>> fixes_;
};

}  // namespace skylit::app::flight
