#include "shading/time_series.h"

#include "shading/sky/atmosphere.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

namespace skylit::shading {
namespace {

constexpr double kSecondsPerDay = 86400.0;
// An END this close to a step counts as on it: the parser reads milliseconds.
constexpr double kOnStepSeconds = 1e-3;

[[noreturn]] void fail(const std::string& message) { throw std::invalid_argument(message); }

std::string quoted(std::string_view text) {
  std::string q(1, '\'');  // appended, not '+': GCC 12 warns falsely (-Wrestrict) on "'" + s
  q.append(text);
  q += '\'';
  return q;
}

std::string count(double n) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f", n);
  return buf;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  return s;
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }

CivilDate parse_date(std::string_view s) {
  const auto field = [&](std::size_t pos, std::size_t n) {
    int v = 0;
    for (std::size_t i = pos; i < pos + n; ++i) v = v * 10 + (s[i] - '0');
    return v;
  };
  const CivilDate d{field(0, 4), field(5, 2), field(8, 2)};
  const std::chrono::year_month_day ymd{std::chrono::year{d.year}, std::chrono::month{static_cast<unsigned>(d.month)},
                                        std::chrono::day{static_cast<unsigned>(d.day)}};
  if (!ymd.ok()) fail("invalid date " + quoted(s) + ": no such day");
  return d;
}

// A comma separates items unless it is a decimal comma inside the seconds
// (09:30:00,5Z): separators are the commas not followed by a digit that does not
// start a new date (YYYY-).
std::vector<std::string_view> split_list(std::string_view text) {
  std::vector<std::string_view> items;
  std::size_t begin = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != ',') continue;
    const std::string_view rest = trim(text.substr(i + 1));
    const bool decimal = !rest.empty() && is_digit(rest.front()) &&
                         !(rest.size() >= 5 && rest[4] == '-' && std::all_of(rest.begin(), rest.begin() + 4, is_digit));
    if (decimal) continue;
    items.push_back(trim(text.substr(begin, i - begin)));
    begin = i + 1;
  }
  items.push_back(trim(text.substr(begin)));
  return items;
}

// `at_most`: frames is an upper bound (a date before its place is known).
void check_frames(double frames, std::size_t limit, const std::string& what, bool at_most = false) {
  if (frames > static_cast<double>(limit))
    fail(what + " would give " + (at_most ? "up to " : "") + count(frames) + " frames, more than the limit of " +
         count(static_cast<double>(limit)));
}

void check_day_step(double step) {
  if (!(step > 0.0) || !std::isfinite(step)) fail("time series: the step of a day must be positive");
}

std::string duration_rule(std::string_view text) {
  return "invalid duration " + quoted(text) + ": expected ISO 8601 P[nD][T[nH][nM][nS]], e.g. PT15M, PT1H30M or P1D";
}

std::vector<sky::UtcTime> parse_interval(std::string_view text, std::size_t max_frames) {
  const std::size_t a = text.find('/');
  const std::size_t b = text.find('/', a + 1);
  const std::string example = "START/END/STEP, e.g. 2026-06-21T04:00Z/2026-06-21T20:00Z/PT15M";
  if (b == std::string_view::npos) fail("time interval " + quoted(text) + " needs a step: " + example);
  if (text.find('/', b + 1) != std::string_view::npos)
    fail("invalid time interval " + quoted(text) + ": expected " + example);
  const sky::UtcTime start = sky::parse_utc_time(trim(text.substr(0, a)));
  const sky::UtcTime end = sky::parse_utc_time(trim(text.substr(a + 1, b - a - 1)));
  const double step = parse_duration_seconds(trim(text.substr(b + 1)));
  if (!(step > 0.0)) fail("time interval " + quoted(text) + ": the step must be positive");
  const double span = end.unix_seconds - start.unix_seconds;
  if (span < 0.0) fail("time interval " + quoted(text) + ": the end is before the start");

  const double whole = std::floor(span / step + kOnStepSeconds / step);
  const bool end_off_step = span - whole * step > kOnStepSeconds;
  check_frames(whole + 1 + (end_off_step ? 1 : 0), max_frames, "time interval " + quoted(text));
  std::vector<sky::UtcTime> out;
  for (double k = 0; k <= whole; ++k) out.push_back({start.unix_seconds + k * step});
  if (end_off_step) out.push_back(end);
  out.back() = end;  // exactly END, also when it is on a step to within a millisecond
  return out;
}

std::vector<sky::UtcTime> parse_list(std::string_view text, std::size_t max_frames) {
  const std::vector<std::string_view> items = split_list(text);
  check_frames(static_cast<double>(items.size()), max_frames, "time list " + quoted(text));
  std::vector<sky::UtcTime> out;
  for (std::size_t k = 0; k < items.size(); ++k) {
    if (items[k].empty()) fail("time list " + quoted(text) + ": item " + std::to_string(k + 1) + " is empty");
    out.push_back(sky::parse_utc_time(items[k]));
    if (k > 0 && !(out[k].unix_seconds > out[k - 1].unix_seconds))
      fail("time list " + quoted(text) + ": times must increase, but " + std::string(items[k]) +
           " is not after " + std::string(items[k - 1]));
  }
  return out;
}

// Apparent (refracted) elevation of the sun's centre, radians: what the lighting uses.
double apparent_elevation(sky::UtcTime t, const sky::Observer& place) {
  return sky::solar_position(t, place).apparent_elevation_deg * std::numbers::pi / 180.0;
}

// The instant in [lo, hi] at which the apparent elevation crosses `target`, given
// that it does so once there (bisection; 2⁻⁴⁰ of a half day is far below 1 ms).
sky::UtcTime crossing(sky::UtcTime lo, sky::UtcTime hi, double target, const sky::Observer& place) {
  const bool rising = apparent_elevation(lo, place) < target;
  double a = lo.unix_seconds, b = hi.unix_seconds;
  for (int i = 0; i < 40; ++i) {
    const double m = 0.5 * (a + b);
    ((apparent_elevation({m}, place) < target) == rising ? a : b) = m;
  }
  return {0.5 * (a + b)};
}

std::string place_text(const sky::Observer& p) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "lat %.4g lon %.4g", p.latitude_deg, p.longitude_deg);
  return buf;
}

std::string date_text(const CivilDate& d) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%04d-%02d-%02d", d.year, d.month, d.day);
  return buf;
}

}  // namespace

bool looks_like_date(std::string_view text) {
  const std::string_view s = trim(text);
  if (s.size() != 10 || s[4] != '-' || s[7] != '-') return false;
  for (std::size_t i : {0, 1, 2, 3, 5, 6, 8, 9})
    if (!is_digit(s[i])) return false;
  return true;
}

double parse_duration_seconds(std::string_view text) {
  std::size_t pos = 0;
  double sign = 1.0;
  if (pos < text.size() && text[pos] == '-') {
    sign = -1.0;
    ++pos;
  }
  if (pos >= text.size() || text[pos] != 'P') fail(duration_rule(text));
  ++pos;
  // Designators in the order they may appear, with their lengths; Y and M before T
  // (years, months) and W are left out: only fixed lengths make a step.
  struct Unit {
    char designator;
    bool time_part;
    double seconds;
  };
  constexpr Unit kUnits[] = {{'D', false, kSecondsPerDay}, {'H', true, 3600.0}, {'M', true, 60.0}, {'S', true, 1.0}};
  std::size_t next_unit = 0;
  bool in_time = false, any = false, fraction_seen = false;
  double total = 0.0;
  while (pos < text.size()) {
    if (text[pos] == 'T') {
      if (in_time) fail(duration_rule(text));
      in_time = true;
      ++pos;
      if (pos == text.size()) fail(duration_rule(text));  // T with no component
      continue;
    }
    if (fraction_seen) fail(duration_rule(text));  // only the last component has a fraction
    const std::size_t start = pos;
    double value = 0.0;
    for (; pos < text.size() && is_digit(text[pos]); ++pos) value = value * 10.0 + (text[pos] - '0');
    if (pos == start) fail(duration_rule(text));
    if (pos < text.size() && (text[pos] == '.' || text[pos] == ',')) {
      ++pos;
      double scale = 0.1;
      const std::size_t frac = pos;
      for (; pos < text.size() && is_digit(text[pos]); ++pos, scale *= 0.1) value += (text[pos] - '0') * scale;
      if (pos == frac) fail(duration_rule(text));
      fraction_seen = true;
    }
    if (pos == text.size()) fail(duration_rule(text));
    const char d = text[pos++];
    if (!in_time && (d == 'Y' || d == 'M' || d == 'W'))
      fail("invalid duration " + quoted(text) + ": years, months and weeks are not supported as a step; use days (P1D) or hours, minutes, seconds (PT1H)");
    std::size_t u = next_unit;
    while (u < std::size(kUnits) && !(kUnits[u].designator == d && kUnits[u].time_part == in_time)) ++u;
    if (u == std::size(kUnits)) fail(duration_rule(text));
    total += value * kUnits[u].seconds;
    next_unit = u + 1;
    any = true;
  }
  if (!any || !std::isfinite(total)) fail(duration_rule(text));
  return sign * total;
}

TimeSpec parse_time_spec(std::string_view raw, const TimeSeriesOptions& options) {
  const std::string_view text = trim(raw);
  check_day_step(options.day_step_seconds);
  TimeSpec spec;
  spec.day_step_seconds = options.day_step_seconds;
  spec.max_frames = options.max_frames;
  if (text.empty()) fail("empty time: expected an ISO 8601 time, list, interval or date");
  if (text.find('/') != std::string_view::npos) {
    spec.instants = parse_interval(text, options.max_frames);
  } else if (looks_like_date(text)) {
    spec.date = parse_date(text);
    // Grid points over at most a day, plus sunrise, sunset and the two disc events.
    check_frames(std::floor(kSecondsPerDay / options.day_step_seconds) + 5, options.max_frames,
                 "the date " + quoted(text) + " at a step of " + number(options.day_step_seconds) + " s", true);
  } else {
    spec.instants = parse_list(text, options.max_frames);
  }
  return spec;
}

bool needs_place(const TimeSpec& spec) { return spec.date.has_value(); }

TimeSeries resolve_time_series(const TimeSpec& spec, const std::optional<sky::Observer>& place) {
  TimeSeries out;
  if (!spec.date) {
    out.instants = spec.instants;
    return out;
  }
  const CivilDate& d = *spec.date;
  if (!place) fail("the date " + date_text(d) + " needs a place (latitude, longitude) for its sunrise and sunset");
  // The local-mean-time day sun_events uses: UTC midnight shifted by longitude/15 h.
  const double day_start = sky::utc_from_civil(d.year, d.month, d.day).unix_seconds -
                           place->longitude_deg / 360.0 * kSecondsPerDay;
  const double day_end = day_start + kSecondsPerDay;
  const sky::SunEvents ev = sky::sun_events({day_start + 0.5 * kSecondsPerDay}, *place);
  const std::string where = date_text(d) + " at " + place_text(*place);
  if (ev.always_down) {
    out.note = "polar night on " + where + ": the sun stays below the horizon all day; no frames";
    return out;
  }
  std::vector<sky::UtcTime> events;  // the frames that are not on the grid
  double start = day_start, end = day_end;
  if (ev.always_up) {
    out.note = "polar day on " + where + ": the sun stays up; frames cover the whole local day (24 h)";
  } else {
    if (ev.sunrise) start = ev.sunrise->unix_seconds;
    if (ev.sunset) end = ev.sunset->unix_seconds;
    if (!ev.sunrise || !ev.sunset)
      out.note = "no " + std::string(ev.sunrise ? "sunset" : "sunrise") + " found on " + where + "; frames " +
                 (ev.sunrise ? "end with" : "begin with") + " the local day";
    // Whole disc risen / about to set, if its centre ever climbs that high.
    const double r = sky::kSunAngularRadius;
    const sky::UtcTime noon = ev.solar_noon;
    if (apparent_elevation(noon, *place) > r && noon.unix_seconds > start && noon.unix_seconds < end) {
      if (apparent_elevation({start}, *place) < r) events.push_back(crossing({start}, noon, r, *place));
      if (apparent_elevation({end}, *place) < r) events.push_back(crossing(noon, {end}, r, *place));
    }
  }
  events.push_back({start});
  events.push_back({end});

  const double step = spec.day_step_seconds;
  check_day_step(step);  // a TimeSpec built by hand, too
  const auto near_event = [&](double t) {
    return std::any_of(events.begin(), events.end(),
                       [&](sky::UtcTime e) { return std::abs(t - e.unix_seconds) < 0.25 * step; });
  };
  out.instants = events;
  for (double k = std::floor(start / step) + 1; k * step < end; ++k)
    if (!near_event(k * step)) out.instants.push_back({k * step});
  std::sort(out.instants.begin(), out.instants.end(),
            [](sky::UtcTime a, sky::UtcTime b) { return a.unix_seconds < b.unix_seconds; });
  check_frames(static_cast<double>(out.instants.size()), spec.max_frames, "the date " + date_text(d));
  return out;
}

std::string format_instant(sky::UtcTime t) {
  const double whole = std::floor(t.unix_seconds);
  const int millis = static_cast<int>(std::lround((t.unix_seconds - whole) * 1000.0));
  if (millis == 0 || millis == 1000) return sky::format_utc_time(t);
  std::string text = sky::format_utc_time({whole});
  char fraction[8];
  std::snprintf(fraction, sizeof fraction, ".%03d", millis);
  return text.insert(text.size() - 1, fraction);
}

}  // namespace skylit::shading
