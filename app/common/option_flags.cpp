#include "app/common/option_flags.h"

#include "shading/lighting.h"
#include "terrain/dem_reader.h"
#include "terrain/raster_writer.h"

#include <string_view>

namespace skylit::app {
namespace {

struct Flag {
  std::string_view option;  // the library's name (a member of its options struct)
  std::string_view before;  // put before the message ("--lat: …")
  std::string_view after;   // or after it ("… with -s/--scale")
};

// terrain::DemReadOptions and StagingOptions: the remedy follows the message.
constexpr Flag kDemFlags[] = {{"scale", "", " with -s/--scale"},
                              {"memory_limit_bytes", "", "; set TMPDIR to a larger disk, or raise --dem-memory"}};
// terrain::RasterWriteOptions.
constexpr Flag kWriteFlags[] = {{"overwrite", "", " (pass --overwrite to replace it)"}};
// shading::LightingRequest: the flag at fault comes first.
constexpr Flag kLightingFlags[] = {
    {"time", "--time: ", ""},
    {"latitude_deg", "--lat: ", ""},
    {"longitude_deg", "--lon: ", ""},
    {"place", "--lat, --lon: ", ""},
    {"sun_azimuth_deg", "--sun-azimuth: ", ""},
    {"sun_elevation_deg", "--sun-elevation: ", ""},
    {"sky", "--sky: ", ""},
    {"turbidity", "--turbidity: ", ""},
    {"sky_scale", "--sky-scale: ", ""},
};

template <std::size_t N>
std::string decorate(const Flag (&flags)[N], const std::string& option, const char* what) {
  for (const Flag& f : flags)
    if (f.option == option) return std::string(f.before) + what + std::string(f.after);
  return what;
}

}  // namespace

std::string message_with_flags(const std::exception& e) {
  if (const auto* d = dynamic_cast<const terrain::DemError*>(&e)) return decorate(kDemFlags, d->option(), e.what());
  if (const auto* w = dynamic_cast<const terrain::RasterWriteError*>(&e))
    return decorate(kWriteFlags, w->option(), e.what());
  if (const auto* l = dynamic_cast<const shading::LightingError*>(&e))
    return decorate(kLightingFlags, l->option(), e.what());
  return e.what();
}

}  // namespace skylit::app
