#include "shading/relief/color_relief.h"

#include <cmath>

namespace skylit::relief {
namespace {

Rgba rgba_of(const ColorEntry& e) {
  return {static_cast<std::uint8_t>(e.r), static_cast<std::uint8_t>(e.g), static_cast<std::uint8_t>(e.b),
          static_cast<std::uint8_t>(e.a)};
}

// gdaldem's rounding of an interpolated channel: +0.45, truncated, clamped.
std::uint8_t mix(int lo, int hi, double t) {
  const int v = static_cast<int>(0.45 + lo + t * (hi - lo));
  return static_cast<std::uint8_t>(v < 0 ? 0 : v > 255 ? 255 : v);
}

}  // namespace

Rgba color_at(const ColorTable& table, double value, ColorSelection selection) {
  const auto& e = table.entries;
  const int n = static_cast<int>(e.size());
  int lower = 0;
  if (std::isnan(e[0].value)) {
    if (std::isnan(value)) return rgba_of(e[0]);
    lower = 1;
  }
  // i: the first entry not below `value` (n when all are), by gdaldem's bisection.
  int i = 0;
  int upper = n - 1;
  while (true) {
    if (upper - lower <= 1) {
      i = value <= e[lower].value ? lower : value <= e[upper].value ? upper : upper + 1;
      break;
    }
    const int mid = (lower + upper) / 2;
    if (e[mid].value >= value) upper = mid;
    else lower = mid;
  }
  const Rgba none{0, 0, 0, 0};
  if (i == 0 || i == n) {
    const ColorEntry& end = e[i == 0 ? 0 : n - 1];
    return selection == ColorSelection::ExactEntry && end.value != value ? none : rgba_of(end);
  }
  const ColorEntry& lo = e[i - 1];
  const ColorEntry& hi = e[i];
  if (lo.value == value) return rgba_of(lo);
  if (selection == ColorSelection::ExactEntry) return none;
  if (selection == ColorSelection::NearestEntry) return rgba_of(value - lo.value < hi.value - value ? lo : hi);
  if (std::isnan(lo.value)) return rgba_of(hi);
  const double t = (value - lo.value) / (hi.value - lo.value);
  return {mix(lo.r, hi.r, t), mix(lo.g, hi.g, t), mix(lo.b, hi.b, t), mix(lo.a, hi.a, t)};
}

}  // namespace skylit::relief
