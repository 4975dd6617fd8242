#include "view/trail_polyline.h"

#include <algorithm>

namespace skylit::view {
namespace {

// find_gaps reads times and validity only: the placed fixes as a track of bare fixes.
std::vector<flight::TrackGap> gaps_between(std::span<const flight::PlacedFix> fixes, double max_gap_s) {
  flight::Track timeline;
  timeline.fixes.resize(fixes.size());
  for (std::size_t k = 0; k < fixes.size(); ++k) timeline.fixes[k].time_s = fixes[k].time_s;
  return flight::find_gaps(timeline, max_gap_s);
}

double climb_rate(const std::vector<TrailVertex>& v, std::size_t k) {
  const std::size_t a = k > 0 ? k - 1 : k, b = k + 1 < v.size() ? k + 1 : k;
  return (v[b].position.z - v[a].position.z) / (v[b].time_s - v[a].time_s);
}

}  // namespace

std::vector<TrailPolyline> trail_polylines(std::span<const flight::PlacedFix> fixes, const ToFieldFrame& to_field,
                                           TrailColour colour, double max_gap_s) {
  const std::vector<flight::TrackGap> gaps = gaps_between(fixes, max_gap_s);
  std::vector<TrailPolyline> out;
  std::vector<TrailVertex> run;
  auto close_run = [&] {
    if (run.size() >= 2) out.push_back({std::move(run)});
    run.clear();
  };
  auto gap = gaps.begin();
  for (const flight::PlacedFix& f : fixes) {
    run.push_back({to_field(f.position), f.time_s});
    if (gap != gaps.end() && gap->start_s == f.time_s) {  // the last fix before the gap
      close_run();
      ++gap;
    }
  }
  close_run();

  double lo = 0.0, hi = 0.0;
  bool first = true;
  for (const TrailPolyline& p : out)
    for (const TrailVertex& v : p.vertices) {
      lo = first ? v.position.z : std::min(lo, v.position.z);
      hi = first ? v.position.z : std::max(hi, v.position.z);
      first = false;
    }
  for (TrailPolyline& p : out)
    for (std::size_t k = 0; k < p.vertices.size(); ++k) {
      TrailVertex& v = p.vertices[k];
      v.value = colour == TrailColour::Altitude ? v.position.z : climb_rate(p.vertices, k);
      v.colour = ramp_colour(colour, ramp_position(colour, v.value, lo, hi));
    }
  return out;
}

}  // namespace skylit::view
