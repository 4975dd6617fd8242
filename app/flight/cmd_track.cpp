// `skylit track FILE`: reads a track file (IGC, GPX, KML gx:Track, CSV), checks it and
// prints what it holds: a short summary, or with --json every fix with its altitude
// channels and their datums. Bad files end in one line and exit code 1.
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "app/commands.h"
#include "app/common/altitude_arg.h"
#include "app/flight/track_report.h"
#include "flight/track_gaps.h"
#include "flight/track_reader.h"

namespace skylit::app::flight {
namespace {

struct TrackArgs {
  std::string file;
  bool json = false;
  std::string altitude;
  double max_gap_s = skylit::flight::kDefaultMaxGapSeconds;
};

int run_track(const TrackArgs& a) {
  ReportOptions o;
  if (!(std::isfinite(a.max_gap_s) && a.max_gap_s > 0.0)) throw std::invalid_argument("--max-gap must be a positive number of seconds");
  o.max_gap_s = a.max_gap_s;
  if (!a.altitude.empty()) o.altitude = parse_altitude_arg(a.altitude);
  const auto tracks = skylit::flight::read_track_file(a.file);
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
                  "Also give each fix's height above the EGM96 geoid from: gnss (ellipsoidal through the geoid), pressure (ISA)");
  cmd->add_option("--max-gap", args->max_gap_s, "Seconds between valid fixes that count as a gap")->capture_default_str();
  cmd->callback([&run, args] { run = [args] { return run_track(*args); }; });
}

}  // namespace skylit::app::flight
