// The --altitude value of the flight commands: gnss, pressure or agl-offset=M
// (flight/altitude.h says what each means).
#pragma once

#include <string>

#include "flight/altitude.h"

namespace skylit::app {

// Throws std::invalid_argument naming --altitude for any other spelling.
skylit::flight::AltitudeMode parse_altitude_arg(const std::string& text);

// "gnss", "pressure", "agl-offset=50".
std::string altitude_arg_name(const skylit::flight::AltitudeMode& mode);

}  // namespace skylit::app
