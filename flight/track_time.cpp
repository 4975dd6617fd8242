#include "flight/track_time.h"

#include <cmath>
#include <cstdio>

namespace skylit::flight {
namespace {

// Days since 1970-01-01 (H. Hinnant's days_from_civil).
long long days_from_civil(long long y, unsigned m, unsigned d) {
  y -= m <= 2;
  const long long era = (y >= 0 ? y : y - 399) / 400;
  const unsigned yoe = static_cast<unsigned>(y - era * 400);
  const unsigned doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + static_cast<long long>(doe) - 719468;
}

void civil_from_days(long long z, int& y, int& m, int& d) {
  z += 719468;
  const long long era = (z >= 0 ? z : z - 146096) / 146097;
  const unsigned doe = static_cast<unsigned>(z - era * 146097);
  const unsigned yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const unsigned doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const unsigned mp = (5 * doy + 2) / 153;
  d = static_cast<int>(doy - (153 * mp + 2) / 5 + 1);
  m = static_cast<int>(mp < 10 ? mp + 3 : mp - 9);
  y = static_cast<int>(static_cast<long long>(yoe) + era * 400 + (m <= 2));
}

// Reads exactly n digits at text[pos...]; advances pos.
bool digits(std::string_view text, std::size_t& pos, int n, int& value) {
  if (pos + n > text.size()) return false;
  value = 0;
  for (int k = 0; k < n; ++k) {
    const char c = text[pos + k];
    if (c < '0' || c > '9') return false;
    value = value * 10 + (c - '0');
  }
  pos += n;
  return true;
}

bool expect(std::string_view text, std::size_t& pos, char c) {
  if (pos >= text.size() || text[pos] != c) return false;
  ++pos;
  return true;
}

}  // namespace

bool is_valid_date(int year, int month, int day) {
  if (month < 1 || month > 12 || day < 1) return false;
  static constexpr int kDays[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
  return day <= kDays[month - 1] + (month == 2 && leap);
}

double seconds_from_civil(int year, int month, int day, int hour, int minute, double second) {
  return static_cast<double>(days_from_civil(year, static_cast<unsigned>(month), static_cast<unsigned>(day))) * 86400.0 +
         hour * 3600.0 + minute * 60.0 + second;
}

std::optional<double> parse_iso8601(std::string_view text, bool assume_utc_without_zone) {
  std::size_t p = 0;
  int y, mo, d, h, mi, s;
  if (!digits(text, p, 4, y) || !expect(text, p, '-') || !digits(text, p, 2, mo) || !expect(text, p, '-') ||
      !digits(text, p, 2, d))
    return std::nullopt;
  if (p >= text.size() || (text[p] != 'T' && text[p] != ' ')) return std::nullopt;
  ++p;
  if (!digits(text, p, 2, h) || !expect(text, p, ':') || !digits(text, p, 2, mi) || !expect(text, p, ':') ||
      !digits(text, p, 2, s))
    return std::nullopt;
  double fraction = 0.0;
  if (p < text.size() && (text[p] == '.' || text[p] == ',')) {
    ++p;
    double scale = 0.1;
    const std::size_t start = p;
    while (p < text.size() && text[p] >= '0' && text[p] <= '9') {
      fraction += (text[p] - '0') * scale;
      scale *= 0.1;
      ++p;
    }
    if (p == start) return std::nullopt;
  }
  // 23:59:60 (a leap second) reads as the next minute's 00, as POSIX time does.
  if (!is_valid_date(y, mo, d) || h > 23 || mi > 59 || s > 60) return std::nullopt;
  double offset_s = 0.0;
  if (p == text.size()) {
    if (!assume_utc_without_zone) return std::nullopt;
  } else if (text[p] == 'Z' || text[p] == 'z') {
    ++p;
  } else if (text[p] == '+' || text[p] == '-') {
    const int sign = text[p] == '-' ? -1 : 1;
    ++p;
    int oh, om = 0;
    if (!digits(text, p, 2, oh)) return std::nullopt;
    if (p < text.size()) {
      expect(text, p, ':');
      if (!digits(text, p, 2, om)) return std::nullopt;
    }
    if (oh > 18 || om > 59) return std::nullopt;
    offset_s = sign * (oh * 3600.0 + om * 60.0);
  } else {
    return std::nullopt;
  }
  if (p != text.size()) return std::nullopt;
  return seconds_from_civil(y, mo, d, h, mi, s + fraction) - offset_s;
}

std::string format_iso8601(double seconds) {
  if (!(std::abs(seconds) < 1e14)) return "(time out of range)";  // beyond ±3 million years
  const double ms_total = std::round(seconds * 1000.0);
  const long long ms = static_cast<long long>(ms_total);
  long long days = ms / 86400000;
  long long rem = ms % 86400000;
  if (rem < 0) {
    rem += 86400000;
    --days;
  }
  int y, m, d;
  civil_from_days(days, y, m, d);
  const int hh = static_cast<int>(rem / 3600000), mm = static_cast<int>(rem / 60000 % 60),
            ss = static_cast<int>(rem / 1000 % 60), frac = static_cast<int>(rem % 1000);
  char buf[40];
  if (frac)
    std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", y, m, d, hh, mm, ss, frac);
  else
    std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%02dZ", y, m, d, hh, mm, ss);
  return buf;
}

}  // namespace skylit::flight
