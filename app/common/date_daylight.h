// `--time 2026-06-21` (a date alone) for the front ends that play a clock (render, the
// viewer): that local day's daylight at a place, as `shade`'s series reads a date
// (shading/time_series.h: local mean solar time, sunrise to sunset).
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <utility>

#include "shading/sky/sun_position.h"

namespace skylit::app {

// Sunrise and sunset (UTC seconds) of `time` when it is a date alone, at `place`;
// nothing when it is anything else (a time: the caller parses it). Polar night throws
// std::invalid_argument (one line: no daylight to show); polar day gives the whole
// local day, with a note on `notes` (if any).
std::optional<std::pair<double, double>> date_daylight(const std::string& time, const sky::Observer& place,
                                                       std::ostream* notes);

}  // namespace skylit::app
