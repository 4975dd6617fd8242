// The flight trail's colour scales (view/trail_polyline.h): one fixed ramp per quantity,
// as sRGB display values (0..1) that go straight into the 8-bit framebuffer, like the
// other passes' colours after their tone curve.
#pragma once

#include <glm/vec3.hpp>

namespace skylit::view {

// Altitude: matplotlib's viridis (perceptually uniform, readable in grey) at its stops
// 0, 1/4, 1/2, 3/4, 1 over the track's lowest..highest fix.
// ClimbRate: ColorBrewer's diverging RdBu (5 classes) from blue (sinking) through
// near-white (level) to red (climbing), over −kClimbClampMps..+kClimbClampMps.
// Both linear in sRGB between their stops.
enum class TrailColour { Altitude, ClimbRate };

// ±5 m/s: a strong thermal's climb; faster climbs and sinks read as the ramp's ends.
inline constexpr double kClimbClampMps = 5.0;

// The ramp's colour at u in [0, 1] (clamped; NaN reads as 0).
glm::vec3 ramp_colour(TrailColour ramp, double u);

// Where a value sits on its ramp: an altitude between lo and hi (the middle when they are
// equal), a climb rate (m/s) on ±kClimbClampMps (lo, hi unused); clamped to [0, 1].
double ramp_position(TrailColour ramp, double value, double lo, double hi);

}  // namespace skylit::view
