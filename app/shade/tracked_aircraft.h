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

#include <optional>
#include <string>
#include <vector>

namespace skylit::app::shade {

class TrackedAircraft {
 public:
  // Throws std::invalid_argument (one line) for a bad track or set, a DEM without a CRS,
  // or a track none of whose fixes can be placed.
  TrackedAircraft(const std::string& track_path, const std::string& aircraft, const skylit::flight::AltitudeMode& altitude,
                  const terrain::HeightField& field);
  // Every track of several files, read in order (the viewer's and render's --track ...).
  TrackedAircraft(const std::vector<std::string>& track_paths, const std::string& aircraft,
                  const skylit::flight::AltitudeMode& altitude, const terrain::HeightField& field);
  // Tracks already read; `source` names them in errors ("--track 'f.igc'").
  TrackedAircraft(const std::vector<skylit::flight::Track>& tracks, const std::string& source,
                  const std::string& aircraft, const skylit::flight::AltitudeMode& altitude,
                  const terrain::HeightField& field);

  // The spheres of every aircraft that has a pose at this time (none in a gap or
  // outside its track's span).
  std::vector<blockers::Sphere> spheres_at(double unix_seconds) const;
  // Track k's aircraft (k: its index among the tracks given) at this time, its position
  // in the field frame; nullopt when it has no pose then or fewer than two placed fixes.
  std::optional<skylit::flight::Pose> pose_at(std::size_t k, double unix_seconds) const;
  std::size_t tracks() const { return samplers_.size(); }
  // Whether track k's aircraft is over the field at one of 65 times from start() to
  // end(): false for a track flown wholly beside the DEM.
  bool over_field(std::size_t k) const;
  // Track k's placed fixes (CRS positions), or null when it has fewer than two.
  const skylit::flight::TrackSampler* sampler(std::size_t k) const { return samplers_[k] ? &*samplers_[k] : nullptr; }
  // A CRS position (a placed fix's) in the field frame, as pose_at places it.
  glm::dvec3 to_field(const glm::dvec3& crs) const;
  const skylit::flight::SphereSet& set() const { return set_; }
  // "glider (30 spheres) on 1 track, 2026-06-21T10:00:00Z to 2026-06-21T10:10:00Z".
  std::string summary() const;
  // The first and last placed fix over all tracks (UTC seconds).
  double start() const { return start_; }
  double end() const { return end_; }

 private:
  void place(const std::vector<skylit::flight::Track>& tracks, const std::string& source,
             const skylit::flight::AltitudeMode& altitude);

  const terrain::HeightField& field_;
  skylit::flight::SphereSet set_;
  std::vector<std::optional<skylit::flight::TrackSampler>> samplers_;  // per track given
  std::size_t placed_ = 0;                                              // tracks with a sampler
  double start_ = 0.0, end_ = 0.0;
};

}  // namespace skylit::app::shade
