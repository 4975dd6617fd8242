#include "app/common/altitude_arg.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace skylit::app {

using skylit::flight::AltitudeMode;
using skylit::flight::AltitudeSource;

AltitudeMode parse_altitude_arg(const std::string& text) {
  if (text == "gnss") return {AltitudeSource::gnss};
  if (text == "pressure") return {AltitudeSource::pressure};
  constexpr std::string_view kAgl = "agl-offset=";
  if (text.starts_with(kAgl)) {
    double m = 0.0;
    const char* first = text.data() + kAgl.size();
    const char* last = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(first, last, m);
    if (ec == std::errc() && ptr == last && first != last && std::isfinite(m)) return {AltitudeSource::agl_offset, m};
  }
  throw std::invalid_argument("--altitude '" + text + "' is not gnss, pressure or agl-offset=METRES");
}

std::string altitude_arg_name(const AltitudeMode& mode) {
  switch (mode.source) {
    case AltitudeSource::gnss: return "gnss";
    case AltitudeSource::pressure: return "pressure";
    case AltitudeSource::agl_offset: {
      char buf[48];
      std::snprintf(buf, sizeof buf, "agl-offset=%g", mode.agl_offset_m);
      return buf;
    }
  }
  return "";
}

}  // namespace skylit::app
