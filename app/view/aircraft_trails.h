// The flight trails of every track of the aircraft, in the field frame, as the window
// and `render` draw them (view/trail_draw.h).
#pragma once

#include <memory>
#include <optional>
#include <string_view>

#include "app/shade/tracked_aircraft.h"
#include "view/trail_colour.h"
#include "view/trail_draw.h"

namespace skylit::app::view {

// Needs a current GL 4.5 context.
std::unique_ptr<skylit::view::TrailDraw> make_trails(const shade::TrackedAircraft& aircraft,
                                                     skylit::view::TrailColour colour);

// `--trail`: "altitude" or "climb" (their colour ramps), or "off".
enum class Trail { Off, Altitude, Climb };
std::optional<Trail> parse_trail(std::string_view name);  // nothing for another name
skylit::view::TrailColour trail_colour(Trail trail);        // not Off

}  // namespace skylit::app::view
