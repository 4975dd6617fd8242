// `skylit track FILE`: reads a track file (IGC, GPX, KML gx:Track, CSV), checks it and
// prints what it holds: a short summary, or with --json every fix with its altitude
// channels and their datums; with --dem also the terrain's light on each fix's aircraft
// (track_terrain.h). Bad files end in one line and exit code 1.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "app/commands.h"
#include "app/common/altitude_arg.h"
#include "app/flight/track_report.h"
#include "app/flight/track_terrain.h"
#include "flight/track_gaps.h"
#include "flight/track_reader.h"

namespace skylit::app::flight {
namespace {

struct TrackArgs {
  std::string file;
  bool json = false;
  std::string altitude;
  double max_gap_s = skylit::flight::kDefaultMaxGapSeconds;
  std::string dem;
  std::string aircraft = "glider";
};

int run_track(const TrackArgs& a) {
  ReportOptions o;
  if (!(std::isfinite(a.max_gap_s) && a.max_gap_s > 0.0)) throw std::invalid_argument("--max-gap must be a positive number of seconds");
  o.max_gap_s = a.max_gap_s;
  if (!a.altitude.empty()) o.altitude = parse_altitude_arg(a.altitude);
  const auto tracks = skylit::flight::read_track_file(a.file);
  std::optional<TrackTerrain> terrain;
  if (!a.dem.empty()) {
    // Placing needs a height: gnss unless --altitude says otherwise, as `shade --track`.
    terrain.emplace(tracks, a.file, a.dem, a.aircraft, o.altitude.value_or(skylit::flight::AltitudeMode{}));
    o.terrain = &*terrain;
  }
  const std::string report = a.json ? track_report_json(a.file, tracks, o) : track_report_text(a.file, tracks, o);
  std::fputs(report.c_str(), stdout);
  return 0;
}

}  // namespace

void add_track_command(CLI::App& root, Action& run) {
  auto args = std::make_shared<TrackArgs>();
  CLI::App* cmd = root.add_subcommand("track", "Read a flight track (IGC, GPX, KML gx:Track, CSV) and summarise it");
  cmd->add_option("file", args->file, "Track file")->required();
  cmd->add_flag("--json", args->json, "Print every fix (UTC time, lat, lon, altitude channels with datums, validity) and a summary as JSON");
  cmd->add_option("--altitude", args->altitude,
                  "Also give each fix's height above the EGM96 geoid from: gnss (ellipsoidal through the geoid), pressure (ISA); "
                  "with --dem also agl-offset=M (metres above the ground)");
  cmd->add_option("--max-gap", args->max_gap_s, "Seconds between valid fixes that count as a gap")->capture_default_str();
  CLI::Option* dem = cmd->add_option(
      "--dem", args->dem,
      "A DEM with a CRS: per fix, the terrain's shadow and sky view on the aircraft (by gnss unless --altitude)");
  cmd->add_option("--aircraft", args->aircraft,
                  "With --dem, the sphere set whose centroid is marched: a shipped name (glider, light-single, "
                  "airliner, helicopter, balloon) or a set.json")
      ->capture_default_str()
      ->needs(dem);
  cmd->callback([&run, args] { run = [args] { return run_track(*args); }; });
}

}  // namespace skylit::app::flight
