// Where an aircraft is and how it is turned at one instant, and the rotation that takes
// its body frame (x forward, y left, z up, metres) to a local east-north-up frame.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace skylit::flight {

// Degrees. heading: clockwise from the frame's north (grid north in a projected CRS);
// pitch: nose up positive; bank: right wing down positive.
struct Attitude {
  double heading_deg = 0.0;
  double pitch_deg = 0.0;
  double bank_deg = 0.0;
};

struct Pose {
  double time_s = 0.0;  // UTC, seconds since 1970-01-01T00:00:00Z
  // x east and y north in the target frame's units (metres), z a height in metres in
  // the target's vertical datum.
  glm::dvec3 position{0.0};
  Attitude attitude;
};

// Columns: the body's forward, left and up axes in east-north-up coordinates.
glm::dmat3 body_to_enu(const Attitude& attitude);

}  // namespace skylit::flight
