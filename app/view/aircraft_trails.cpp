#include "app/view/aircraft_trails.h"

#include <vector>

#include "view/trail_polyline.h"

namespace skylit::app::view {

std::unique_ptr<skylit::view::TrailDraw> make_trails(const shade::TrackedAircraft& aircraft,
                                                     skylit::view::TrailColour colour) {
  std::vector<skylit::view::TrailPolyline> lines;
  for (std::size_t k = 0; k < aircraft.tracks(); ++k)
    if (const flight::TrackSampler* s = aircraft.sampler(k)) {
      std::vector<skylit::view::TrailPolyline> l = skylit::view::trail_polylines(
          s->fixes(), [&aircraft](const glm::dvec3& p) { return aircraft.to_field(p); }, colour);
      lines.insert(lines.end(), l.begin(), l.end());
    }
  return std::make_unique<skylit::view::TrailDraw>(lines);
}

std::optional<Trail> parse_trail(std::string_view name) {
  if (name == "altitude") return Trail::Altitude;
  if (name == "climb") return Trail::Climb;
  if (name == "off") return Trail::Off;
  return std::nullopt;
}

skylit::view::TrailColour trail_colour(Trail trail) {
  return trail == Trail::Climb ? skylit::view::TrailColour::ClimbRate : skylit::view::TrailColour::Altitude;
}

}  // namespace skylit::app::view
