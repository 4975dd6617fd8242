// Heights to RGBA through a colour table, as gdaldem color-relief computes each pixel:
// linear interpolation between the bracketing entries with each channel truncated after
// adding 0.45 (gdaldem's rounding), the end entries' colours beyond the ends; or the exact
// entry (else transparent black), or the nearest entry (ties to the upper one).
#pragma once

#include "shading/relief/color_table.h"

#include <array>
#include <cstdint>

namespace skylit::relief {

enum class ColorSelection { Interpolate, ExactEntry, NearestEntry };

using Rgba = std::array<std::uint8_t, 4>;

// The colour of height `value` (NaN selects a NaN nodata entry, if any).
Rgba color_at(const ColorTable& table, double value, ColorSelection selection);

}  // namespace skylit::relief
