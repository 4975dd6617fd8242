// What `skylit track` prints about the tracks of a file: every fix with each altitude
// channel and its datum (JSON), or a short summary per track (text); with a DEM, the
// terrain's light on each fix's aircraft (track_terrain.h) in both.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/flight/track_terrain.h"
#include "flight/altitude.h"
#include "flight/track.h"

namespace skylit::app::flight {

struct ReportOptions {
  double max_gap_s = 0.0;
  // When set, each fix also gets its height in the DEM datum (EGM96 MSL) by this mode.
  std::optional<skylit::flight::AltitudeMode> altitude;
  // When set (--dem), each fix's terrain object and each track's terrain summary; it also
  // gives agl-offset heights the ground they need.
  const TrackTerrain* terrain = nullptr;
};

std::string track_report_json(const std::string& file, const std::vector<skylit::flight::Track>& tracks,
                              const ReportOptions& options);
std::string track_report_text(const std::string& file, const std::vector<skylit::flight::Track>& tracks,
                              const ReportOptions& options);

}  // namespace skylit::app::flight
