#include "app/flight/track_report.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "app/common/altitude_arg.h"
#include "flight/track_gaps.h"
#include "flight/track_time.h"

namespace skylit::app::flight {
namespace {

namespace fl = skylit::flight;
using nlohmann::json;

json altitude_json(const fl::Altitude& a) { return {{"m", a.metres}, {"datum", fl::datum_name(a.datum)}}; }

std::size_t invalid_count(const fl::Track& t) {
  return static_cast<std::size_t>(std::count_if(t.fixes.begin(), t.fixes.end(), [](const fl::Fix& f) { return !f.valid; }));
}

// agl-offset heights need the ground: the terrain's placement has it.
bool heights_from_terrain(const ReportOptions& o) {
  return o.altitude && o.altitude->source == fl::AltitudeSource::agl_offset && o.terrain;
}

// Heights of every fix of track k by the requested mode (nullopt: the fix has none);
// checks that the mode can place some fix of the track.
std::vector<std::optional<double>> heights(const fl::Track& t, std::size_t k, const ReportOptions& o,
                                           const std::optional<fl::AltitudeResolver>& resolver) {
  std::vector<std::optional<double>> h;
  h.reserve(t.fixes.size());
  if (heights_from_terrain(o)) {
    for (std::size_t i = 0; i < t.fixes.size(); ++i) {
      const auto& f = o.terrain->at(k, i);
      h.push_back(f ? std::optional<double>(f->height_m) : std::nullopt);
    }
    return h;
  }
  if (!resolver->usable(t))
    throw std::invalid_argument("track '" + t.id + "' has no altitude that --altitude " + altitude_arg_name(*o.altitude) +
                                " can use");
  // Invalid fixes are never placed, so they get no height.
  for (const fl::Fix& f : t.fixes) h.push_back(f.valid ? resolver->height(f, 0.0, 0.0) : std::nullopt);
  return h;
}

std::optional<fl::AltitudeResolver> make_resolver(const ReportOptions& o) {
  if (!o.altitude || heights_from_terrain(o)) return std::nullopt;
  if (o.altitude->source == fl::AltitudeSource::agl_offset)
    throw std::invalid_argument("--altitude agl-offset needs the ground under the aircraft, and skylit track reads no DEM "
                                "without --dem (give one, or use gnss or pressure)");
  return fl::AltitudeResolver(*o.altitude);
}

json terrain_json(const FixTerrain& t) {
  auto optional = [](const std::optional<double>& v) { return v ? json(*v) : json(nullptr); };
  return {{"inside_dem", t.inside_dem},
          {"below_ground", t.below_ground},
          {"ground_m", optional(t.ground_m)},
          {"height_above_ground_m", optional(t.height_above_ground_m)},
          {"sun_azimuth_deg", t.sun_azimuth_deg},
          {"sun_elevation_deg", t.sun_elevation_deg},
          {"sun_horizon_deg", t.sun_horizon_deg},
          {"in_terrain_shadow", t.in_terrain_shadow},
          {"sun_visible_fraction", t.sun_visible_fraction},
          {"sky_view", t.sky_view},
          {"sky_fraction", t.sky_fraction}};
}

json terrain_summary_json(const TrackTerrain& terrain, std::size_t k) {
  const TrackTerrainSummary s = terrain.summary(k);
  const bool any = s.over_dem > 0;
  return {{"dem", terrain.dem()},
          {"aircraft", terrain.aircraft()},
          {"point", "volume-weighted centroid of the set's spheres"},
          {"fixes", s.fixes},
          {"fixes_over_dem", s.over_dem},
          {"in_terrain_shadow", s.in_shadow},
          {"in_terrain_shadow_fraction", any ? json(static_cast<double>(s.in_shadow) / s.over_dem) : json(nullptr)},
          {"sky_view_min", any ? json(s.sky_view_min) : json(nullptr)},
          {"sky_view_mean", any ? json(s.sky_view_mean) : json(nullptr)}};
}

std::string channels(const fl::Track& t) {
  bool gnss = false, pressure = false, stated = false;
  fl::AltitudeDatum gd{}, sd{};
  for (const fl::Fix& f : t.fixes) {
    if (f.gnss) gnss = true, gd = f.gnss->datum;
    if (f.pressure) pressure = true;
    if (f.stated) stated = true, sd = f.stated->datum;
  }
  std::string s;
  auto add = [&](const std::string& part) { s += (s.empty() ? "" : ", ") + part; };
  if (gnss) add(std::string("gnss (") + fl::datum_name(gd) + ")");
  if (pressure) add("pressure (pressure-isa)");
  if (stated) add(std::string("stated (") + fl::datum_name(sd) + ")");
  return s.empty() ? "none" : s;
}

}  // namespace

std::string track_report_json(const std::string& file, const std::vector<fl::Track>& tracks, const ReportOptions& o) {
  const auto resolver = make_resolver(o);
  json out{{"file", file}};
  json jt = json::array();
  std::size_t total = 0, invalid = 0;
  double start = std::numeric_limits<double>::infinity(), end = -start;
  for (std::size_t n = 0; n < tracks.size(); ++n) {
    const fl::Track& t = tracks[n];
    std::vector<std::optional<double>> h;
    if (o.altitude) h = heights(t, n, o, resolver);
    json fixes = json::array();
    for (std::size_t k = 0; k < t.fixes.size(); ++k) {
      const fl::Fix& f = t.fixes[k];
      json jf{{"time", fl::format_iso8601(f.time_s)}, {"lat", f.lat_deg}, {"lon", f.lon_deg}, {"valid", f.valid}};
      if (f.gnss) jf["gnss"] = altitude_json(*f.gnss);
      if (f.pressure) jf["pressure"] = altitude_json(*f.pressure);
      if (f.stated) jf["stated"] = altitude_json(*f.stated);
      if (o.altitude) jf["height_msl_m"] = h[k] ? json(*h[k]) : json(nullptr);
      if (f.ground_speed_mps) jf["ground_speed_mps"] = *f.ground_speed_mps;
      if (f.track_deg) jf["track_deg"] = *f.track_deg;
      if (f.vertical_rate_mps) jf["vertical_rate_mps"] = *f.vertical_rate_mps;
      if (!f.extensions.empty()) {
        json ext = json::object();
        for (const fl::FixExtension& e : f.extensions) ext[e.code] = e.value;
        jf["extensions"] = ext;
      }
      if (o.terrain) jf["terrain"] = o.terrain->at(n, k) ? terrain_json(*o.terrain->at(n, k)) : json(nullptr);
      fixes.push_back(std::move(jf));
    }
    json gaps = json::array();
    for (const fl::TrackGap& g : fl::find_gaps(t, o.max_gap_s))
      gaps.push_back({{"start", fl::format_iso8601(g.start_s)}, {"length_s", g.length_s}});
    const double t0 = t.fixes.front().time_s, t1 = t.fixes.back().time_s;
    json summary{{"start", fl::format_iso8601(t0)}, {"end", fl::format_iso8601(t1)}, {"duration_s", t1 - t0},
                 {"fixes", t.fixes.size()}, {"invalid_fixes", invalid_count(t)}, {"gaps", gaps}};
    if (o.altitude) summary["altitude"] = altitude_arg_name(*o.altitude);
    if (o.terrain) summary["terrain"] = terrain_summary_json(*o.terrain, n);
    jt.push_back({{"id", t.id}, {"callsign", t.callsign}, {"format", fl::format_name(t.format)}, {"summary", summary},
                  {"fixes", fixes}});
    total += t.fixes.size();
    invalid += invalid_count(t);
    start = std::min(start, t0);
    end = std::max(end, t1);
  }
  out["summary"] = {{"tracks", tracks.size()}, {"fixes", total}, {"invalid_fixes", invalid},
                    {"start", fl::format_iso8601(start)}, {"end", fl::format_iso8601(end)}, {"duration_s", end - start},
                    {"max_gap_s", o.max_gap_s}};
  out["tracks"] = std::move(jt);
  return out.dump(1) + "\n";
}

std::string track_report_text(const std::string& file, const std::vector<fl::Track>& tracks, const ReportOptions& o) {
  const auto resolver = make_resolver(o);
  std::string s = file + ": " + std::to_string(tracks.size()) + (tracks.size() == 1 ? " track" : " tracks") + " (" +
                  fl::format_name(tracks.front().format) + ")\n";
  char buf[256];
  for (std::size_t n = 0; n < tracks.size(); ++n) {
    const fl::Track& t = tracks[n];
    const double t0 = t.fixes.front().time_s, t1 = t.fixes.back().time_s;
    const auto gaps = fl::find_gaps(t, o.max_gap_s);
    std::snprintf(buf, sizeof buf, "%s%s%s: %s to %s (%.0f s), %zu fixes, %zu invalid, %zu gap%s over %g s\n",
                  t.id.empty() ? "(unnamed)" : t.id.c_str(), t.callsign.empty() ? "" : " ", t.callsign.c_str(),
                  fl::format_iso8601(t0).c_str(), fl::format_iso8601(t1).c_str(), t1 - t0, t.fixes.size(),
                  invalid_count(t), gaps.size(), gaps.size() == 1 ? "" : "s", o.max_gap_s);
    s += buf;
    for (const fl::TrackGap& g : gaps) {
      std::snprintf(buf, sizeof buf, "  gap at %s, %.0f s\n", fl::format_iso8601(g.start_s).c_str(), g.length_s);
      s += buf;
    }
    s += "  altitude channels: " + channels(t) + "\n";
    if (o.altitude) {
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (const auto& h : heights(t, n, o, resolver))
        if (h) lo = std::min(lo, *h), hi = std::max(hi, *h);
      std::snprintf(buf, sizeof buf, "  height (%s, EGM96 MSL): %.1f to %.1f m\n", altitude_arg_name(*o.altitude).c_str(), lo, hi);
      // agl-offset over a DEM that none of this track's fixes lies on: no height at all.
      s += lo <= hi ? std::string(buf) : "  height (" + altitude_arg_name(*o.altitude) + ", EGM96 MSL): none\n";
    }
    if (o.terrain) {
      const TrackTerrainSummary ts = o.terrain->summary(n);
      s += "  terrain (" + o.terrain->dem() + ", " + o.terrain->aircraft() + "): ";
      std::snprintf(buf, sizeof buf, "%zu of %zu fixes over the DEM", ts.over_dem, ts.fixes);
      s += buf;
      if (ts.over_dem > 0) {
        std::snprintf(buf, sizeof buf, ", %.1f%% in terrain shadow, sky view min %.3f, mean %.3f",
                      100.0 * ts.in_shadow / ts.over_dem, ts.sky_view_min, ts.sky_view_mean);
        s += buf;
      }
      s += "\n";
    }
  }
  return s;
}

}  // namespace skylit::app::flight
