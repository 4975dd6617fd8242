// Poses of an aircraft at any time from its track (DESIGN.md "Aircraft"): the position
// interpolated linearly in the target frame between placed fixes, never across a gap
// (flight/track_gaps.h) and never from an invalid fix; the attitude from the motion,
// assuming coordinated flight:
//  * heading: the course in the target frame (grid heading in a projected CRS);
//  * pitch: atan(v_z / v_h), the flight-path angle;
//  * bank: atan(v_h · ω / g), ω the rate of change of the heading (a coordinated turn's
//    lift balances weight and the centripetal force), positive turning right.
// Smoothing: velocities are averages over a window of ±window_s around the instant
// (clipped to the fix data around it); v_h is the path length along the fixes over the
// window divided by its duration (a chord would shorten it on a circle), ω the heading
// change between the windows centred at t ± window_s. Slower than still_speed_mps the
// aircraft keeps its last moving heading with no pitch and no bank, so poses are finite
// everywhere.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "flight/pose.h"
#include "flight/track.h"
#include "flight/track_gaps.h"

namespace skylit::flight {

struct SamplerOptions {
  double max_gap_s = kDefaultMaxGapSeconds;
  double window_s = 2.0;         // ±2 s: a few 1 s fixes, short against a ~25 s thermal circle
  double still_speed_mps = 0.5;  // below: standing still (GNSS noise on the ground)
};

// A fix placed in the target frame.
struct PlacedFix {
  double time_s = 0.0;
  glm::dvec3 position{0.0};
};

// WGS 84 lon/lat (degrees) → target frame x, y.
using Projection = std::function<glm::dvec2(double lon_deg, double lat_deg)>;
// A fix's height in the target's vertical datum at its (x, y); nullopt: none.
using HeightOf = std::function<std::optional<double>(const Fix& fix, double x, double y)>;

class TrackSampler {
 public:
  // Places the track's valid fixes that have a height; the others are left out.
  TrackSampler(const Track& track, const Projection& project, const HeightOf& height, SamplerOptions options = {});
  // Already placed fixes (strictly increasing times).
  explicit TrackSampler(std::vector<PlacedFix> fixes, SamplerOptions options = {});

  const std::vector<PlacedFix>& fixes() const { return fixes_; }

  // nullopt outside the placed fixes' time span and inside gaps.
  std::optional<glm::dvec3> position_at(double time_s) const;
  std::optional<Pose> pose_at(double time_s) const;

 private:
  struct Motion {
    glm::dvec2 direction{0.0};  // horizontal displacement over the window
    double horizontal_speed = 0.0, vertical_speed = 0.0;
  };
  void index_segments();
  std::optional<std::size_t> bracket(double t) const;  // i with t in [t_i, t_{i+1}] in one segment
  glm::dvec3 interpolate(std::size_t i, double t) const;
  Motion motion(std::size_t segment, double t) const;
  double heading_deg(std::size_t segment, double t, std::size_t at_fix) const;

  std::vector<PlacedFix> fixes_;
  std::vector<std::size_t> segment_;  // per fix: index of its segment's first fix
  std::vector<std::size_t> segment_end_;  // per fix: index of its segment's last fix
  std::vector<double> moving_heading_;    // per fix: heading at the fix, carried over stops
  SamplerOptions options_;
};

}  // namespace skylit::flight
