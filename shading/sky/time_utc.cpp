#include "shading/sky/time_utc.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace skylit::sky {
namespace {

constexpr double kSecondsPerDay = 86400.0;
constexpr double kJulianDayOfUnixEpoch = 2440587.5;

long long days_from_civil(int year, int month, int day) {
  using namespace std::chrono;
  const sys_days d{std::chrono::year{year} / std::chrono::month{static_cast<unsigned>(month)} /
                   std::chrono::day{static_cast<unsigned>(day)}};
  return d.time_since_epoch().count();
}

[[noreturn]] void fail(std::string_view text, const std::string& why) {
  throw std::invalid_argument("invalid time '" + std::string(text) + "': " + why);
}

[[noreturn]] void fail_syntax(std::string_view text) {
  fail(text, "expected ISO 8601 with a zone, e.g. 2026-06-21T09:30:00Z or 2026-06-21T11:30:00+02:00");
}

// Reads exactly `n` digits at `pos`, advancing it.
int read_digits(std::string_view text, std::size_t& pos, int n) {
  if (pos + n > text.size()) fail_syntax(text);
  int value = 0;
  for (int i = 0; i < n; ++i) {
    const char c = text[pos + i];
    if (c < '0' || c > '9') fail_syntax(text);
    value = value * 10 + (c - '0');
  }
  pos += n;
  return value;
}

void expect(std::string_view text, std::size_t& pos, char c) {
  if (pos >= text.size() || text[pos] != c) fail_syntax(text);
  ++pos;
}

void check_range(std::string_view text, const char* field, int value, int lo, int hi) {
  if (value < lo || value > hi)
    fail(text, std::string(field) + " " + std::to_string(value) + " outside " + std::to_string(lo) + "-" +
                   std::to_string(hi));
}

}  // namespace

UtcTime utc_from_civil(int year, int month, int day, int hour, int minute, double second) {
  const double days = static_cast<double>(days_from_civil(year, month, day));
  return {days * kSecondsPerDay + hour * 3600.0 + minute * 60.0 + second};
}

UtcTime parse_utc_time(std::string_view text) {
  std::size_t pos = 0;
  const int year = read_digits(text, pos, 4);
  expect(text, pos, '-');
  const int month = read_digits(text, pos, 2);
  expect(text, pos, '-');
  const int day = read_digits(text, pos, 2);
  if (pos >= text.size() || (text[pos] != 'T' && text[pos] != 't' && text[pos] != ' '))
    fail(text, "a time of day is required, e.g. 2026-06-21T09:30:00Z");
  ++pos;
  const int hour = read_digits(text, pos, 2);
  expect(text, pos, ':');
  const int minute = read_digits(text, pos, 2);
  double second = 0.0;
  if (pos < text.size() && text[pos] == ':') {
    ++pos;
    second = read_digits(text, pos, 2);
    if (pos < text.size() && (text[pos] == '.' || text[pos] == ',')) {
      ++pos;
      double scale = 0.1;
      const std::size_t start = pos;
      for (; pos < text.size() && text[pos] >= '0' && text[pos] <= '9'; ++pos, scale *= 0.1)
        second += (text[pos] - '0') * scale;
      if (pos == start) fail_syntax(text);
    }
  }
  if (pos == text.size())
    fail(text,
         "no time zone; UTC must be explicit: append Z (e.g. 2026-06-21T09:30:00Z) or an offset "
         "such as +02:00");
  int offset_minutes = 0;
  if (text[pos] == 'Z' || text[pos] == 'z') {
    ++pos;
  } else if (text[pos] == '+' || text[pos] == '-') {
    const int sign = text[pos] == '-' ? -1 : 1;
    ++pos;
    const int off_h = read_digits(text, pos, 2);
    int off_m = 0;
    if (pos < text.size()) {
      if (text[pos] == ':') ++pos;
      off_m = read_digits(text, pos, 2);
    }
    check_range(text, "zone offset hour", off_h, 0, 23);
    check_range(text, "zone offset minute", off_m, 0, 59);
    offset_minutes = sign * (off_h * 60 + off_m);
  } else {
    fail_syntax(text);
  }
  if (pos != text.size()) fail_syntax(text);

  check_range(text, "month", month, 1, 12);
  const unsigned last_day = static_cast<unsigned>(
      (std::chrono::year{year} / std::chrono::month{static_cast<unsigned>(month)} / std::chrono::last).day());
  check_range(text, "day", day, 1, static_cast<int>(last_day));
  check_range(text, "hour", hour, 0, 23);
  check_range(text, "minute", minute, 0, 59);
  // 60 is a leap second; POSIX time folds it into the next minute.
  if (second >= 61.0) check_range(text, "second", static_cast<int>(second), 0, 60);

  UtcTime t = utc_from_civil(year, month, day, hour, minute, second);
  t.unix_seconds -= offset_minutes * 60.0;
  return t;
}

std::string format_utc_time(UtcTime t) {
  using namespace std::chrono;
  const long long total = std::llround(t.unix_seconds);
  long long days = total / 86400;
  long long secs = total % 86400;
  if (secs < 0) {
    secs += 86400;
    --days;
  }
  const year_month_day ymd{sys_days{std::chrono::days{days}}};
  char buf[32];
  std::snprintf(buf, sizeof buf, "%04d-%02u-%02uT%02lld:%02lld:%02lldZ", static_cast<int>(ymd.year()),
                static_cast<unsigned>(ymd.month()), static_cast<unsigned>(ymd.day()), secs / 3600,
                secs / 60 % 60, secs % 60);
  return buf;
}

double julian_day(UtcTime t) { return kJulianDayOfUnixEpoch + t.unix_seconds / kSecondsPerDay; }

UtcTime utc_from_julian_day(double jd) { return {(jd - kJulianDayOfUnixEpoch) * kSecondsPerDay}; }

double decimal_year(UtcTime t) {
  using namespace std::chrono;
  const auto day = static_cast<long long>(std::floor(t.unix_seconds / kSecondsPerDay));
  const int y = static_cast<int>(year_month_day{sys_days{std::chrono::days{day}}}.year());
  const double start = utc_from_civil(y, 1, 1).unix_seconds;
  const double end = utc_from_civil(y + 1, 1, 1).unix_seconds;
  return y + (t.unix_seconds - start) / (end - start);
}

}  // namespace skylit::sky
