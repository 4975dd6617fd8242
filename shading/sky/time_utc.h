// UTC instants at the interface: ISO 8601 parsing with a mandatory zone,
// formatting, and the Julian Day the solar ephemeris needs.
#pragma once

#include <string>
#include <string_view>

namespace skylit::sky {

// An instant as POSIX seconds since 1970-01-01T00:00:00Z (no leap seconds,
// so a leap second 23:59:60 reads as the next minute's 00).
struct UtcTime {
  double unix_seconds = 0.0;
};

// Parses YYYY-MM-DD(T|space)hh:mm[:ss[.fff]] followed by Z or ±hh[:mm].
// A time without a zone is rejected: UTC must be explicit. Throws
// std::invalid_argument with a one-line message naming the rule or the field
// out of range.
UtcTime parse_utc_time(std::string_view text);

// YYYY-MM-DDThh:mm:ssZ, rounded to the nearest second.
std::string format_utc_time(UtcTime t);

// Proleptic Gregorian calendar fields to an instant (fields not range-checked).
UtcTime utc_from_civil(int year, int month, int day, int hour = 0, int minute = 0, double second = 0.0);

// Julian Day (UT) and back. JD 2440587.5 is the POSIX epoch.
double julian_day(UtcTime t);
UtcTime utc_from_julian_day(double jd);

// Year with fraction (2000.0 at 2000-01-01T00:00Z), for ΔT models.
double decimal_year(UtcTime t);

}  // namespace skylit::sky
