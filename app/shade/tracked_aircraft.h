// `--track FILE [--aircraft NAME|set.json] [--altitude …]`: the aircraft of a flight track
// (every track of the file) as sphere blockers at a frame's time, in the renderer's field
// frame: poses from flight/track_sampler.h in the DEM's CRS, the sphere set placed at
// each (flight/sphere_set.h).
#pragma once

#include "flight/altitude.h"
#include "flight/sphere_set.h"
#include "flight/track_sampler.h"
#include "shading/blockers/sphere_blocker.h"
#include "terrain/height_field.h"

#include <string>
#include <vector>

namespace skylit::app::shade {

class TrackedAircraft {
 public:
  // Throws std::invalid_argument (one line) for a bad track or set, a DEM without a CRS,
  // or a track none of whose fixes can be placed.
  TrackedAircraft(const std::string& track_path, const std::string& aircraft, const skylit::flight::AltitudeMode& altitude,
                  const terrain::HeightField& field);

  // The spheres of every aircraft that has a pose at this time (none in a gap or
  // outside its track's span).
  std::vector<blockers::Sphere> spheres_at(double unix_seconds) const;
  // "glider (30 spheres) on 1 track, 2026-06-21T10:00:00Z to 2026-06-21T10:10:00Z".
  std::string summary() const;
  // The first and last placed fix over all tracks (UTC seconds).
  double start() const { return start_; }
  double end() const { return end_; }

 private:
  const terrain::HeightField& field_;
  skylit::flight::SphereSet set_;
  std::vector<skylit::flight::TrackSampler> samplers_;
  double start_ = 0.0, end_ = 0.0;
};

}  // namespace skylit::app::shade
