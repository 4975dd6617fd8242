// Where a track has no data to place the aircraft: intervals between consecutive valid
// fixes longer than a threshold. The sampler never interpolates across one.
#pragma once

#include <vector>

#include "flight/track.h"

namespace skylit::flight {

// 15 s: longer than the usual fix intervals (IGC loggers log every 1–5 s in flight,
// OpenSky's historical state vectors come every 10 s), shorter than a thermal circle
// (≈ 20–30 s), across which a straight chord would cut through the circle.
inline constexpr double kDefaultMaxGapSeconds = 15.0;

struct TrackGap {
  double start_s = 0.0;   // time of the last valid fix before the gap
  double length_s = 0.0;  // to the next valid fix
};

// Gaps between consecutive valid fixes (invalid fixes do not close a gap).
std::vector<TrackGap> find_gaps(const Track& track, double max_gap_s = kDefaultMaxGapSeconds);

}  // namespace skylit::flight
