#include "flight/csv_reader.h"

#include <algorithm>
#include <cctype>
#include <map>

#include "flight/track_input.h"
#include "flight/track_time.h"
#include "flight/xml_track_util.h"

namespace skylit::flight {
namespace {

using detail::fail;

enum Column { kTime, kLat, kLon, kIcao24, kCallsign, kVelocity, kHeading, kVertRate, kBaro, kGeo, kAlt, kColumns };

// Header spellings of each column.
const std::map<std::string, Column>& column_names() {
  static const std::map<std::string, Column> names = {
      {"time", kTime},           {"timestamp", kTime},         {"lat", kLat},
      {"latitude", kLat},        {"lon", kLon},                {"lng", kLon},
      {"longitude", kLon},       {"icao24", kIcao24},          {"callsign", kCallsign},
      {"velocity", kVelocity},   {"heading", kHeading},        {"true_track", kHeading},
      {"vertrate", kVertRate},   {"vertical_rate", kVertRate}, {"baroaltitude", kBaro},
      {"baro_altitude", kBaro},  {"geoaltitude", kGeo},        {"geo_altitude", kGeo},
      {"alt", kAlt},             {"altitude", kAlt},           {"ele", kAlt},
      {"elevation", kAlt}};
  return names;
}

std::string trim_lower(std::string_view s, bool lower) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') s = s.substr(1, s.size() - 2);
  std::string out(s);
  if (lower) std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::tolower(c); });
  return out;
}

std::vector<std::string> split(const std::string& line, bool lower) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    fields.push_back(trim_lower(std::string_view(line).substr(start, comma == std::string::npos ? std::string::npos : comma - start), lower));
    if (comma == std::string::npos) return fields;
    start = comma + 1;
  }
}

}  // namespace

std::vector<Track> read_csv(std::istream& in, const std::string& name) {
  detail::LineReader lines(in, name);
  std::string line;
  std::vector<int> index(kColumns, -1);
  bool header = false;
  while (!header && lines.next(line)) {
    if (trim_lower(line, false).empty()) continue;
    const auto fields = split(line, true);
    for (std::size_t k = 0; k < fields.size(); ++k) {
      const auto it = column_names().find(fields[k]);
      if (it != column_names().end() && index[it->second] < 0) index[it->second] = static_cast<int>(k);
    }
    header = true;
  }
  if (!header) fail(name, "empty file");
  if (index[kTime] < 0 || index[kLat] < 0 || index[kLon] < 0)
    fail(name, 1, "CSV header must name the columns time, lat and lon (OpenSky: time,icao24,lat,lon,...; plain: time,lat,lon,alt)");

  std::vector<Track> tracks;
  std::map<std::string, std::size_t> by_icao24;
  std::size_t total = 0;
  while (lines.next(line)) {
    if (trim_lower(line, false).empty()) continue;
    const std::size_t n = lines.line_number();
    const auto fields = split(line, false);
    auto field = [&](Column c) -> const std::string* {
      return index[c] >= 0 && static_cast<std::size_t>(index[c]) < fields.size() && !fields[index[c]].empty()
                 ? &fields[index[c]] : nullptr;
    };
    auto number = [&](Column c, const char* what) -> std::optional<double> {
      const std::string* f = field(c);
      if (!f) return std::nullopt;
      double v;
      if (!detail::parse_number(*f, v)) fail(name, n, std::string(what) + " " + detail::quoted(*f) + " is not a number");
      return v;
    };
    const auto lat = number(kLat, "lat"), lon = number(kLon, "lon");
    if (!lat || !lon) continue;  // OpenSky rows without a position
    detail::check_coordinates(name, n, *lat, *lon);
    Fix fix;
    fix.lat_deg = *lat;
    fix.lon_deg = *lon;
    const std::string* t = field(kTime);
    if (!t) fail(name, n, "row without a time");
    double seconds;
    if (detail::parse_number(*t, seconds)) fix.time_s = seconds;
    else if (const auto iso = parse_iso8601(*t, true)) fix.time_s = *iso;
    else fail(name, n, "time " + detail::quoted(*t) + " is neither POSIX seconds nor ISO 8601");
    if (const auto v = number(kGeo, "geoaltitude")) fix.gnss = Altitude{*v, AltitudeDatum::wgs84_ellipsoid};
    if (const auto v = number(kBaro, "baroaltitude")) fix.pressure = Altitude{*v, AltitudeDatum::pressure_isa};
    if (const auto v = number(kAlt, "alt")) fix.stated = Altitude{*v, AltitudeDatum::geoid_msl};
    fix.ground_speed_mps = number(kVelocity, "velocity");
    fix.track_deg = number(kHeading, "heading");
    fix.vertical_rate_mps = number(kVertRate, "vertrate");

    const std::string key = field(kIcao24) ? *field(kIcao24) : std::string();
    auto [it, fresh] = by_icao24.try_emplace(key, tracks.size());
    if (fresh) {
      tracks.emplace_back();
      tracks.back().format = TrackFormat::csv;
      tracks.back().id = detail::clean_name(key);
    }
    Track& track = tracks[it->second];
    if (track.callsign.empty() && field(kCallsign)) track.callsign = detail::clean_name(*field(kCallsign));
    if (++total > detail::kMaxFixes) fail(name, n, "more than " + std::to_string(detail::kMaxFixes) + " fixes");
    detail::append_fix(track, std::move(fix), name, n);
  }
  detail::require_fixes(tracks, name, "no rows with a time, lat and lon");
  return tracks;
}

}  // namespace skylit::flight
