// `skylit sun`: solar azimuth, elevation and the day's rise/noon/set for a
// place and a UTC instant (NREL SPA, shading/sky/sun_position.h).
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "app/commands.h"
#include "shading/sky/sun_position.h"
#include "shading/sky/time_utc.h"

namespace skylit::app::shade {
namespace {

struct SunOptions {
  double lat = 0.0;
  double lon = 0.0;
  std::string time;
  double height = 0.0;
  double pressure = 1010.0;
  double temperature = 10.0;
  bool json = false;
};

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument("sun: " + message);
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

void validate(const SunOptions& o) {
  require(std::isfinite(o.lat) && std::abs(o.lat) <= 90.0,
          "--lat " + number(o.lat) + " outside -90..90 degrees");
  require(std::isfinite(o.lon) && std::abs(o.lon) <= 180.0,
          "--lon " + number(o.lon) + " outside -180..180 degrees");
  require(std::isfinite(o.height), "--height must be a finite number of metres");
  require(std::isfinite(o.pressure) && o.pressure > 0.0, "--pressure must be positive (mbar)");
  require(std::isfinite(o.temperature) && o.temperature > -273.15, "--temperature must be above -273.15 C");
}

std::string json_time(const std::optional<sky::UtcTime>& t) {
  return t ? "\"" + sky::format_utc_time(*t) + "\"" : "null";
}

std::string text_time(const std::optional<sky::UtcTime>& t, const sky::SunEvents& ev) {
  if (t) return sky::format_utc_time(*t);
  if (ev.always_up) return "none (sun above the horizon all day)";
  if (ev.always_down) return "none (sun below the horizon all day)";
  return "none";
}

int run_sun(const SunOptions& o) {
  validate(o);
  const sky::UtcTime t = sky::parse_utc_time(o.time);
  const sky::Observer observer{o.lat, o.lon, o.height};
  const sky::SolarPosition p = sky::solar_position(t, observer, {o.pressure, o.temperature});
  const sky::SunEvents ev = sky::sun_events(t, observer);

  if (o.json) {
    std::printf(
        "{\"azimuth_deg\": %.6f, \"elevation_deg\": %.6f, \"apparent_elevation_deg\": %.6f, "
        "\"sunrise\": %s, \"solar_noon\": %s, \"sunset\": %s}\n",
        p.azimuth_deg, p.elevation_deg, p.apparent_elevation_deg, json_time(ev.sunrise).c_str(),
        json_time(ev.solar_noon).c_str(), json_time(ev.sunset).c_str());
    return 0;
  }
  std::printf("time                %s\n", sky::format_utc_time(t).c_str());
  std::printf("azimuth             %.4f deg (from north, clockwise)\n", p.azimuth_deg);
  std::printf("elevation           %.4f deg (true, topocentric)\n", p.elevation_deg);
  std::printf("apparent elevation  %.4f deg (refraction at %g mbar, %g C)\n", p.apparent_elevation_deg,
              o.pressure, o.temperature);
  std::printf("sunrise             %s\n", text_time(ev.sunrise, ev).c_str());
  std::printf("solar noon          %s\n", sky::format_utc_time(ev.solar_noon).c_str());
  std::printf("sunset              %s\n", text_time(ev.sunset, ev).c_str());
  return 0;
}

}  // namespace

void add_sun_command(CLI::App& root, Action& run) {
  auto opts = std::make_shared<SunOptions>();
  auto* cmd = root.add_subcommand(
      "sun",
      "Sun position (NREL SPA) for a place and UTC time, and that local day's sunrise, solar noon "
      "and sunset in UTC (the day is the observer's mean-solar-time day containing --time)");
  cmd->add_option("--lat", opts->lat, "Latitude, degrees north (-90..90)")->required();
  cmd->add_option("--lon", opts->lon, "Longitude, degrees east (-180..180)")->required();
  cmd->add_option(
         "--time", opts->time,
         "ISO 8601 time with an explicit zone, e.g. 2026-06-21T09:30:00Z or 2026-06-21T11:30:00+02:00")
      ->required();
  cmd->add_option("--height", opts->height, "Observer height above sea level, m")->capture_default_str();
  cmd->add_option("--pressure", opts->pressure, "Air pressure for refraction, mbar")->capture_default_str();
  cmd->add_option("--temperature", opts->temperature, "Air temperature for refraction, C")
      ->capture_default_str();
  cmd->add_flag("--json", opts->json,
                "Print one JSON object: azimuth_deg, elevation_deg, apparent_elevation_deg, sunrise, "
                "solar_noon, sunset (ISO 8601 UTC or null)");
  cmd->callback([&run, opts] { run = [opts] { return run_sun(*opts); }; });
}

}  // namespace skylit::app::shade
