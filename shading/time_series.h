// Time series: a time specification as the user writes it, parsed into UTC instants.
//
// Forms (ISO 8601; every time needs a zone, time_utc.h):
//  * one time                  2026-06-21T09:30Z
//  * a list                    2026-06-21T09:30Z,2026-06-21T12:00+02:00   (increasing)
//  * START/END/STEP            2026-06-21T04:00Z/2026-06-21T20:00Z/PT15M
//      START + k·STEP up to END; END is included when it falls on a step (to 1 ms),
//      otherwise it is added as a last, shorter step, so that an integral over the
//      frames covers [START, END]. (The start/end/resolution triple of OGC WMS TIME.)
//  * a date alone              2026-06-21
//      that day in local mean solar time at a place (sun_events' day: UTC shifted by
//      longitude/15 h, not the civil zone, which a DEM does not carry), from sunrise
//      to sunset: the sunrise and sunset instants, the instants the whole disc has
//      risen / is about to set (apparent elevation of its centre = its radius: with
//      them a flat horizon's rise and set are integrated exactly, so the step is
//      free to be coarse), and every multiple of the step since 1970-01-01T00:00Z
//      in between, less those within a quarter step of these events. Polar day: the
//      whole local day (24 h) at the step, with a note; polar night: no frames and a
//      note.
//
// Parsing needs no place (so a request is checked before any DEM is read); a date is
// resolved against one afterwards (resolve_time_series).
#pragma once

#include "shading/sky/sun_position.h"
#include "shading/sky/time_utc.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace skylit::shading {

// Step of a date alone, measured against a 1-minute step to keep daily insolation
// within 0.5 % and sun hours within 2 min (docs/time-step.md, bench/time_step_report).
inline constexpr double kDefaultDayStepSeconds = 5 * 60.0;
inline constexpr std::size_t kDefaultMaxFrames = 10000;

struct TimeSeriesOptions {
  std::size_t max_frames = kDefaultMaxFrames;          // more frames is an error
  double day_step_seconds = kDefaultDayStepSeconds;    // step of a date alone (> 0)
};

struct CivilDate {
  int year = 0, month = 0, day = 0;
};

// A parsed specification: explicit instants, or a date still to be resolved at a place.
struct TimeSpec {
  std::vector<sky::UtcTime> instants;  // strictly increasing; empty for a date
  std::optional<CivilDate> date;
  double day_step_seconds = kDefaultDayStepSeconds;
  std::size_t max_frames = kDefaultMaxFrames;
};

// An ISO 8601 duration, the subset with fixed lengths: P[nD][T[nH][nM][nS]] (integers;
// the last component may have a decimal fraction), e.g. P1D, PT1H30M, PT0.5S. A
// leading '-' parses, so that a negative step reads as such. Throws
// std::invalid_argument (one line) otherwise.
double parse_duration_seconds(std::string_view text);

// Throws std::invalid_argument (one line) for: a malformed time, interval or
// duration; a step ≤ 0; END before START; list items that are empty or not
// increasing; a time without a zone; a date that does not exist; more than
// options.max_frames frames (a date: more than a whole day at the step could give).
TimeSpec parse_time_spec(std::string_view text, const TimeSeriesOptions& options = {});

// True when the specification is a date, whose frames depend on the place.
bool needs_place(const TimeSpec& spec);
// True when the text has the shape of a date alone, YYYY-MM-DD (surrounding spaces
// aside), whether or not that day exists.
bool looks_like_date(std::string_view text);

struct TimeSeries {
  std::vector<sky::UtcTime> instants;  // strictly increasing
  std::string note;                    // one line when a date has no sunrise/sunset
};

// ISO 8601 of an instant, to the millisecond where it is not a whole second (a date's
// sunrise and disc events fall between seconds): what parse_utc_time reads back.
std::string format_instant(sky::UtcTime t);

// The instants of `spec`; a date needs `place` (e.g. the DEM's centre), else throws
// std::invalid_argument.
TimeSeries resolve_time_series(const TimeSpec& spec, const std::optional<sky::Observer>& place);

}  // namespace skylit::shading
