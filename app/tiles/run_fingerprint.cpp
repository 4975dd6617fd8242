#include "app/tiles/run_fingerprint.h"

#include <cstdio>
#include <filesystem>
#include <sstream>

namespace skylit::app::tiles {
namespace {

std::string exact(double v) {  // round-trips: equal options give equal text
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string optional_number(const std::optional<double>& v) { return v ? exact(*v) : "-"; }

}  // namespace

std::string run_fingerprint(const RunOptions& o) {
  namespace fs = std::filesystem;
  std::ostringstream f;
  f << "skylit=" << SKYLIT_VERSION << "\n";
  for (std::size_t i = 0; i < o.inputs.size(); ++i) {
    // A folder of tiles (no file size) or an unreadable stat records 0: still the same
    // text for the same input.
    std::error_code path_ec, size_ec, time_ec;
    const fs::path p = fs::weakly_canonical(fs::absolute(o.inputs[i]), path_ec);
    const auto size = fs::file_size(p, size_ec);
    const auto mtime = fs::last_write_time(p, time_ec).time_since_epoch().count();
    f << "dem" << (i + 1) << "=" << p.string() << " " << (size_ec ? 0 : size) << " bytes, mtime "
      << (time_ec ? 0 : mtime) << "\n";
  }
  f << "product=" << o.product << "\n"
    << "quality=" << o.quality << "\n"
    << "zoom=" << o.zooms.min << "-" << o.zooms.max << "\n"
    << "tile-size=" << o.tile_size << "\n"
    << "format=" << skylit::tiles::format_name(o.format) << "\n"
    << "rows=" << (o.tms ? "tms" : "xyz") << "\n"
    << "resampling=" << (o.resampling.empty() ? "default" : o.resampling) << "\n";
  f << "halo/max-distance=";
  for (const ZoomPlan& p : o.plans) f << "z" << p.z << ":" << p.halo << "/" << exact(p.max_distance_m) << " ";
  f << "\n";
  const shading::LightingRequest& l = o.light;
  f << "time=" << (l.time.empty() ? "-" : l.time) << "\n"
    << "lat/lon=" << optional_number(l.latitude_deg) << "/" << optional_number(l.longitude_deg) << "\n"
    << "sun-azimuth/elevation=" << optional_number(l.sun_azimuth_deg) << "/" << optional_number(l.sun_elevation_deg)
    << "\n"
    << "sun=" << (l.sun ? "on" : "off") << "\n"
    << "sky=" << l.sky << " turbidity " << exact(l.turbidity) << " scale " << exact(l.sky_scale) << "\n"
    << "tone=" << o.tone << "\n";
  // Runs without bounds keep the text they had, so their archives still resume.
  if (o.bounds)
    f << "bounds=" << exact(o.bounds->west) << "," << exact(o.bounds->south) << "," << exact(o.bounds->east) << ","
      << exact(o.bounds->north) << "\n";
  return f.str();
}

}  // namespace skylit::app::tiles
