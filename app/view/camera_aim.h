// What the cameras of `render` and the viewer aim at: the followed aircraft while its
// track has a pose. Through a gap in the track (invalid fixes, a logger's pause) the
// aim holds where the aircraft was last seen, as the aircraft itself stays undrawn,
// rather than flying to the field's centre and back; before any pose it is the centre.
#pragma once

#include <cstddef>
#include <optional>

#include "app/shade/tracked_aircraft.h"
#include "terrain/height_field.h"
#include "view/camera.h"

namespace skylit::app::view {

class CameraAim {
 public:
  // The field must outlive the aim.
  explicit CameraAim(const terrain::HeightField& field) : field_(field) {}
  // Heights (the target's z) drawn × exaggeration.
  skylit::view::CameraTarget at(const std::optional<shade::TrackedAircraft>& aircraft, std::size_t track,
                                double unix_seconds, double exaggeration);

 private:
  const terrain::HeightField& field_;
  std::optional<skylit::view::CameraTarget> last_;  // the last pose's, heights as they are
};

}  // namespace skylit::app::view
