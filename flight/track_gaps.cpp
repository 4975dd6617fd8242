#include "flight/track_gaps.h"

namespace skylit::flight {

std::vector<TrackGap> find_gaps(const Track& track, double max_gap_s) {
  std::vector<TrackGap> gaps;
  const Fix* previous = nullptr;
  for (const Fix& f : track.fixes) {
    if (!f.valid) continue;
    if (previous && f.time_s - previous->time_s > max_gap_s) gaps.push_back({previous->time_s, f.time_s - previous->time_s});
    previous = &f;
  }
  return gaps;
}

}  // namespace skylit::flight
