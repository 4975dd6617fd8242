// UTC instants as the track formats write them. flight/ links terrain only, so it cannot
// use shading/sky/time_utc.h; this is the small subset the readers need (the calendar
// arithmetic is the same proleptic-Gregorian day count).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace skylit::flight {

// Seconds since 1970-01-01T00:00:00Z of a proleptic Gregorian date and time of day.
double seconds_from_civil(int year, int month, int day, int hour = 0, int minute = 0, double second = 0.0);

// True when year-month-day is a calendar date.
bool is_valid_date(int year, int month, int day);

// ISO 8601 date-time: YYYY-MM-DD(T| )hh:mm:ss[.f...] followed by Z, ±hh:mm, ±hhmm or
// ±hh. A time without a zone is read as UTC when `assume_utc_without_zone` (CSV), and
// rejected otherwise. nullopt when the text is not such a time.
std::optional<double> parse_iso8601(std::string_view text, bool assume_utc_without_zone = false);

// YYYY-MM-DDThh:mm:ss[.sss]Z: milliseconds only when the instant has them.
std::string format_iso8601(double seconds);

}  // namespace skylit::flight
