#include "flight/igc_reader.h"

#include <cstdlib>
#include <string_view>

#include "flight/track_input.h"
#include "flight/track_time.h"

namespace skylit::flight {
namespace {

using detail::fail;

constexpr std::size_t kBRecordBytes = 35;  // B HHMMSS DDMMmmmN DDDMMmmmE V PPPPP GGGGG
constexpr double kSecondsPerDay = 86400.0;

bool all_digits(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s)
    if (c < '0' || c > '9') return false;
  return true;
}

int to_int(std::string_view s) {
  int v = 0;
  for (char c : s) v = v * 10 + (c - '0');
  return v;
}

// Five characters: 5 digits, or '-' and 4 digits.
bool parse_altitude(std::string_view s, int& metres) {
  if (s.size() != 5) return false;
  if (s[0] == '-') {
    if (!all_digits(s.substr(1))) return false;
    metres = -to_int(s.substr(1));
    return true;
  }
  if (!all_digits(s)) return false;
  metres = to_int(s);
  return true;
}

struct Extension {
  std::size_t first, last;  // 1-based inclusive byte range, as the I record gives it
  std::string code;
};

struct IgcState {
  std::string name;
  std::optional<double> day_start_s;  // midnight UTC of the current date header
  double day_offset_s = 0.0;           // whole days added by midnight wraps
  std::optional<double> last_time_of_day;
  AltitudeDatum gnss_datum = AltitudeDatum::wgs84_ellipsoid;
  std::vector<Extension> extensions;
  std::string glider_id, competition_id, logger_id;
  bool any_pressure = false, any_gnss = false;
};

void parse_date_header(IgcState& st, std::string_view line, std::size_t n) {
  std::string_view rest = line.substr(5);  // after "HFDTE"
  if (rest.starts_with("DATE")) rest.remove_prefix(4);
  if (rest.starts_with(":")) rest.remove_prefix(1);
  if (rest.size() < 6 || !all_digits(rest.substr(0, 6)))
    fail(st.name, n, "date header " + detail::quoted(std::string(line)) + " is not HFDTEddmmyy or HFDTEDATE:ddmmyy,NN");
  const int d = to_int(rest.substr(0, 2)), m = to_int(rest.substr(2, 2)), yy = to_int(rest.substr(4, 2));
  const int y = yy < 80 ? 2000 + yy : 1900 + yy;
  if (!is_valid_date(y, m, d)) fail(st.name, n, "date header " + detail::quoted(std::string(line)) + " is not a calendar date");
  st.day_start_s = seconds_from_civil(y, m, d);
  st.day_offset_s = 0.0;
  st.last_time_of_day.reset();
}

void parse_i_record(IgcState& st, std::string_view line, std::size_t n) {
  if (line.size() < 3 || !all_digits(line.substr(1, 2))) fail(st.name, n, "I record without its extension count");
  const int count = to_int(line.substr(1, 2));
  if (line.size() < 3 + 7 * static_cast<std::size_t>(count))
    fail(st.name, n, "I record announces " + std::to_string(count) + " extensions but is too short");
  st.extensions.clear();
  for (int k = 0; k < count; ++k) {
    const std::string_view e = line.substr(3 + 7 * k, 7);
    if (!all_digits(e.substr(0, 4))) fail(st.name, n, "I record extension " + std::to_string(k + 1) + " has no byte range");
    const std::size_t first = to_int(e.substr(0, 2)), last = to_int(e.substr(2, 2));
    if (first <= kBRecordBytes || last < first)
      fail(st.name, n, "I record extension " + detail::quoted(e.substr(4, 3)) + " has bytes " + std::to_string(first) + "-" +
                           std::to_string(last) + " (must follow byte 35)");
    st.extensions.push_back({first, last, std::string(e.substr(4, 3))});
  }
}

// Degrees from DDMMmmm (lat, 2 degree digits) or DDDMMmmm (lon, 3), hemisphere letter.
bool parse_angle(std::string_view s, int degree_digits, char positive, char negative, double& deg) {
  const std::string_view num = s.substr(0, s.size() - 1);
  const char hemi = s.back();
  if (!all_digits(num) || (hemi != positive && hemi != negative)) return false;
  const int whole = to_int(num.substr(0, degree_digits));
  const int thousandths_of_minute = to_int(num.substr(degree_digits));
  if (thousandths_of_minute >= 60000) return false;
  deg = whole + thousandths_of_minute / 60000.0;
  if (hemi == negative) deg = -deg;
  return true;
}

void parse_b_record(IgcState& st, Track& track, std::string_view line, std::size_t n) {
  if (line.size() < kBRecordBytes) fail(st.name, n, "B record shorter than 35 bytes");
  if (!st.day_start_s) fail(st.name, n, "B record before any date header (HFDTE)");
  const std::string_view hms = line.substr(1, 6);
  if (!all_digits(hms)) fail(st.name, n, "B record time " + detail::quoted(std::string(hms)) + " is not HHMMSS");
  const int h = to_int(hms.substr(0, 2)), mi = to_int(hms.substr(2, 2)), s = to_int(hms.substr(4, 2));
  if (h > 23 || mi > 59 || s > 59) fail(st.name, n, "B record time " + detail::quoted(std::string(hms)) + " out of range");
  const double tod = h * 3600.0 + mi * 60.0 + s;
  if (st.last_time_of_day && tod < *st.last_time_of_day - kSecondsPerDay / 2) st.day_offset_s += kSecondsPerDay;
  st.last_time_of_day = tod;

  Fix fix;
  fix.time_s = *st.day_start_s + st.day_offset_s + tod;
  if (!parse_angle(line.substr(7, 8), 2, 'N', 'S', fix.lat_deg))
    fail(st.name, n, "B record latitude " + detail::quoted(std::string(line.substr(7, 8))) + " is not DDMMmmmN/S");
  if (!parse_angle(line.substr(15, 9), 3, 'E', 'W', fix.lon_deg))
    fail(st.name, n, "B record longitude " + detail::quoted(std::string(line.substr(15, 9))) + " is not DDDMMmmmE/W");
  detail::check_coordinates(st.name, n, fix.lat_deg, fix.lon_deg);
  const char validity = line[24];
  if (validity != 'A' && validity != 'V') fail(st.name, n, "B record validity " + detail::quoted(std::string(1, validity)) + " is not A or V");
  fix.valid = validity == 'A';
  int pressure, gnss;
  if (!parse_altitude(line.substr(25, 5), pressure) || !parse_altitude(line.substr(30, 5), gnss))
    fail(st.name, n, "B record altitudes " + detail::quoted(std::string(line.substr(25, 10))) + " are not two 5-character numbers");
  fix.pressure = Altitude{static_cast<double>(pressure), AltitudeDatum::pressure_isa};
  // A V fix has no 3-D GNSS solution: its GNSS altitude (loggers write 00000) means nothing.
  if (fix.valid || gnss != 0) fix.gnss = Altitude{static_cast<double>(gnss), st.gnss_datum};
  st.any_pressure |= pressure != 0;
  st.any_gnss |= gnss != 0;
  for (const Extension& e : st.extensions)
    if (e.last <= line.size()) fix.extensions.push_back({e.code, std::string(line.substr(e.first - 1, e.last - e.first + 1))});
  detail::append_fix(track, std::move(fix), st.name, n);
}

void parse_header(IgcState& st, std::string_view line, std::size_t n) {
  // H records: H, source (F/O/P), three-letter code, then free text up to a ':'.
  if (line.size() < 5) return;
  const std::string_view code = line.substr(2, 3);
  const auto colon = line.find(':');
  const std::string_view value = colon == std::string_view::npos ? std::string_view{} : line.substr(colon + 1);
  if (code == "DTE") parse_date_header(st, line, n);
  else if (code == "GID") st.glider_id = std::string(value);
  else if (code == "CID") st.competition_id = std::string(value);
  else if (code == "ALG") {
    // AL7/AL8: HFALGALTGPS:GEO (geoid) or ELL (ellipsoid); NKN/NIL keep the spec's ellipsoid.
    if (value.starts_with("GEO")) st.gnss_datum = AltitudeDatum::geoid_msl;
    else if (value.starts_with("ELL")) st.gnss_datum = AltitudeDatum::wgs84_ellipsoid;
  }
}

}  // namespace

std::vector<Track> read_igc(std::istream& in, const std::string& name) {
  detail::LineReader lines(in, name);
  IgcState st;
  st.name = name;
  Track track;
  track.format = TrackFormat::igc;
  std::string line;
  bool any_line = false;
  while (lines.next(line)) {
    if (line.empty()) continue;
    any_line = true;
    const std::size_t n = lines.line_number();
    switch (line[0]) {
      case 'A': if (st.logger_id.empty()) st.logger_id = line.substr(1); break;
      case 'H': parse_header(st, line, n); break;
      case 'I': parse_i_record(st, line, n); break;
      case 'B': parse_b_record(st, track, line, n); break;
      default: break;  // C, D, E, F, G, K, L records: not needed for placement
    }
  }
  if (!any_line) fail(name, "empty file");
  if (track.fixes.empty()) fail(name, st.day_start_s ? "no B records (fixes)" : "no B records (fixes) and no date header (HFDTE)");
  for (Fix& f : track.fixes) {
    if (!st.any_pressure) f.pressure.reset();
    if (!st.any_gnss) f.gnss.reset();
  }
  track.id = detail::clean_name(!st.glider_id.empty() ? st.glider_id : !st.competition_id.empty() ? st.competition_id : st.logger_id);
  std::vector<Track> out;
  out.push_back(std::move(track));
  return out;
}

}  // namespace skylit::flight
