// A flight trail as data (pure CPU, no GL): a track's placed fixes in the field frame,
// cut into unbroken polylines at its gaps, each vertex coloured on a trail ramp
// (view/trail_colour.h). view/trail_draw.h draws them.
#pragma once

#include <glm/vec3.hpp>

#include <functional>
#include <span>
#include <vector>

#include "flight/track_gaps.h"
#include "flight/track_sampler.h"
#include "view/trail_colour.h"

namespace skylit::view {

struct TrailVertex {
  glm::dvec3 position{0.0};  // field frame (x east, y north, z up, m), z not exaggerated
  double time_s = 0.0;       // UTC, seconds since 1970
  double value = 0.0;        // what the colour shows: altitude (m) or climb rate (m/s)
  glm::vec3 colour{0.0f};    // sRGB 0..1
};

// Consecutive vertices with no gap between them (at least two).
struct TrailPolyline {
  std::vector<TrailVertex> vertices;
};

// A placed fix's position (the DEM's CRS x, y; z in the DEM's datum) → the field frame.
// The caller passes the mapping that places the aircraft (app/shade/sphere_input.h's
// to_field_frame, as TrackedAircraft::pose_at does), so trail and aircraft coincide.
using ToFieldFrame = std::function<glm::dvec3(const glm::dvec3& crs)>;

// One track's trail from its placed fixes (TrackSampler::fixes(): valid, with a height,
// increasing times), broken at the gaps flight::find_gaps finds between them, the
// intervals where the sampler places no aircraft; a fix alone between gaps makes no
// line. Altitude: the field-frame z on the ramp over the trail's lowest..highest vertex.
// ClimbRate: dz/dt by central differences within a polyline (one-sided at its ends), so
// never across a gap.
std::vector<TrailPolyline> trail_polylines(std::span<const flight::PlacedFix> fixes, const ToFieldFrame& to_field,
                                           TrailColour colour, double max_gap_s = flight::kDefaultMaxGapSeconds);

}  // namespace skylit::view
