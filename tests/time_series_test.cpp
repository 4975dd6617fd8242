// Time specifications (time_series.h): single times, lists, START/END/STEP intervals,
// ISO 8601 durations, a date resolved sunrise to sunset at a place (polar day and
// night included), and the one-line errors. Expected instants are written out by hand
// from the calendar (utc_from_civil), sunrise and sunset from sun_events.
#include "shading/time_series.h"

#include "shading/sky/atmosphere.h"
#include "shading/sky/sun_position.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace skylit::shading {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

double at(int h, int m, double s = 0.0) { return sky::utc_from_civil(2026, 6, 21, h, m, s).unix_seconds; }

// The message of the std::invalid_argument `f` throws; fails the test if none.
std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  ADD_FAILURE() << "no std::invalid_argument";
  return {};
}

// Library messages: one line, no command-line flag.
void expect_clean(const std::string& message) {
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  EXPECT_EQ(message.find("--"), std::string::npos) << message;
}

TEST(TimeSpec, OneTimeIsOneInstant) {
  const TimeSpec s = parse_time_spec("2026-06-21T09:30Z");
  ASSERT_EQ(s.instants.size(), 1u);
  EXPECT_EQ(s.instants[0].unix_seconds, at(9, 30));
  EXPECT_FALSE(needs_place(s));
  EXPECT_EQ(resolve_time_series(s, std::nullopt).instants.size(), 1u);
}

TEST(TimeSpec, ListKeepsZonesAndDecimalCommas) {
  const TimeSpec s = parse_time_spec("2026-06-21T09:30Z, 2026-06-21T12:00+02:00,2026-06-21T10:00:00,5Z");
  ASSERT_EQ(s.instants.size(), 3u);
  EXPECT_EQ(s.instants[0].unix_seconds, at(9, 30));
  EXPECT_EQ(s.instants[1].unix_seconds, at(10, 0));
  EXPECT_EQ(s.instants[2].unix_seconds, at(10, 0, 0.5));
}

TEST(TimeSpec, IntervalIncludesAnEndOnAStep) {
  const TimeSpec s = parse_time_spec("2026-06-21T04:00Z/2026-06-21T20:00Z/PT15M");
  ASSERT_EQ(s.instants.size(), 16u * 4 + 1);
  for (std::size_t k = 0; k < s.instants.size(); ++k) EXPECT_EQ(s.instants[k].unix_seconds, at(4, 0) + 900.0 * k);
  EXPECT_EQ(s.instants.back().unix_seconds, at(20, 0));
}

TEST(TimeSpec, IntervalEndsWithAShorterStepWhenTheEndIsOffTheGrid) {
  const TimeSpec s = parse_time_spec("2026-06-21T04:00Z/2026-06-21T05:10Z/PT30M");
  ASSERT_EQ(s.instants.size(), 4u);
  EXPECT_EQ(s.instants[2].unix_seconds, at(5, 0));
  EXPECT_EQ(s.instants[3].unix_seconds, at(5, 10));
  EXPECT_EQ(parse_time_spec("2026-06-21T04:00Z/2026-06-21T04:00Z/PT1H").instants.size(), 1u);
}

TEST(TimeSpec, DurationsOfFixedLength) {
  EXPECT_EQ(parse_duration_seconds("P1D"), 86400.0);
  EXPECT_EQ(parse_duration_seconds("PT1H"), 3600.0);
  EXPECT_EQ(parse_duration_seconds("PT15M"), 900.0);
  EXPECT_EQ(parse_duration_seconds("PT30S"), 30.0);
  EXPECT_EQ(parse_duration_seconds("PT1H30M"), 5400.0);
  EXPECT_EQ(parse_duration_seconds("P1DT12H"), 129600.0);
  EXPECT_EQ(parse_duration_seconds("PT1M0.5S"), 60.5);
  EXPECT_EQ(parse_duration_seconds("PT0,25H"), 900.0);
  EXPECT_EQ(parse_duration_seconds("-PT15M"), -900.0);
  for (const char* bad : {"", "15M", "P", "PT", "P1Y", "P1M", "P1W", "P1H", "PT1M1H", "PT1.5H30M", "PT15",
                          "PT15MX", "PT1HT1M", "pt15m", "P1.D"})
    expect_clean(error_of([&] { parse_duration_seconds(bad); }));
  EXPECT_NE(error_of([] { parse_duration_seconds("P1M"); }).find("months"), std::string::npos);
}

TEST(TimeSpec, ErrorsAreOneLineWithoutFlagNames) {
  const std::string day = "2026-06-21T04:00Z/2026-06-21T20:00Z/";
  const struct {
    std::string text;
    std::string says;
  } cases[] = {
      {day + "PT0S", "positive"},
      {day + "-PT15M", "positive"},
      {"2026-06-21T20:00Z/2026-06-21T04:00Z/PT15M", "before the start"},
      {day + "PT1S", "57601 frames"},
      {"2026-06-21T04:00Z/2026-06-21T20:00Z", "needs a step"},
      {day + "PT1M/PT1M", "START/END/STEP"},
      {day + "15M", "duration"},
      {"2026-06-21T09:30Z,,2026-06-21T10:30Z", "item 2 is empty"},
      {"2026-06-21T09:30Z,", "item 2 is empty"},
      {"2026-06-21T10:30Z,2026-06-21T09:30Z", "must increase"},
      {"2026-06-21T09:30Z,2026-06-21T09:30Z", "must increase"},
      {"2026-06-21T09:30", "no time zone"},
      {"2026-06-21T09:30Z/2026-06-21T10:00/PT1M", "no time zone"},
      {"2026-02-30", "no such day"},
      {"", "empty time"},
      {"tomorrow", "ISO 8601"},
  };
  for (const auto& c : cases) {
    const std::string m = error_of([&] { parse_time_spec(c.text); });
    EXPECT_NE(m.find(c.says), std::string::npos) << c.text << " -> " << m;
    expect_clean(m);
  }
  // The caller's limit, and a date whose day could exceed it at its step.
  TimeSeriesOptions small;
  small.max_frames = 3;
  EXPECT_NE(error_of([&] { parse_time_spec("2026-06-21T04:00Z/2026-06-21T05:00Z/PT20M", small); }).find("4 frames"),
            std::string::npos);
  EXPECT_EQ(parse_time_spec("2026-06-21T04:00Z/2026-06-21T05:00Z/PT30M", small).instants.size(), 3u);
  TimeSeriesOptions fine;
  fine.day_step_seconds = 1.0;
  expect_clean(error_of([&] { parse_time_spec("2026-06-21", fine); }));
  fine.day_step_seconds = 0.0;
  expect_clean(error_of([&] { parse_time_spec("2026-06-21", fine); }));
}

// Apparent elevation (rad) of the sun's centre, as the lighting sees it.
double elevation(sky::UtcTime t, const sky::Observer& p) {
  return sky::solar_position(t, p).apparent_elevation_deg * kDeg;
}

TEST(TimeSeriesDay, SunriseToSunsetWithTheDiscEventsAndTheStepGrid) {
  const sky::Observer place{45.0, 7.0, 0.0};
  const TimeSpec spec = parse_time_spec("2026-06-21");
  ASSERT_TRUE(needs_place(spec));
  EXPECT_NE(error_of([&] { resolve_time_series(spec, std::nullopt); }).find("needs a place"), std::string::npos);
  const TimeSeries ts = resolve_time_series(spec, place);
  EXPECT_TRUE(ts.note.empty()) << ts.note;
  const sky::SunEvents ev = sky::sun_events(sky::parse_utc_time("2026-06-21T12:00+00:28"), place);
  ASSERT_TRUE(ev.sunrise && ev.sunset);
  const auto& t = ts.instants;
  ASSERT_GE(t.size(), 4u);
  EXPECT_EQ(t.front().unix_seconds, ev.sunrise->unix_seconds);
  EXPECT_EQ(t.back().unix_seconds, ev.sunset->unix_seconds);
  // 45° N at the solstice: cos H0 = (sin(−0.8333°) − sin φ sin δ)/(cos φ cos δ) with
  // δ = 23.44° gives H0 = 117.1°, a day of 2·H0/15° = 15.62 h.
  EXPECT_NEAR((t.back().unix_seconds - t.front().unix_seconds) / 3600.0, 15.62, 0.02);
  // Between them: two off-grid frames, the whole disc just risen and about to set,
  // and every multiple of the step not within a quarter step of those four events.
  const double step = kDefaultDayStepSeconds;
  std::vector<double> events = {t.front().unix_seconds, t.back().unix_seconds};
  for (std::size_t k = 1; k + 1 < t.size(); ++k)
    if (std::fmod(t[k].unix_seconds, step) != 0.0) {
      EXPECT_NEAR(elevation(t[k], place), sky::kSunAngularRadius, 1e-6) << k;
      events.push_back(t[k].unix_seconds);
    }
  ASSERT_EQ(events.size(), 4u);
  std::size_t expected_frames = 4;
  for (double g = std::ceil(t.front().unix_seconds / step) * step; g < t.back().unix_seconds; g += step)
    expected_frames += std::all_of(events.begin(), events.end(), [&](double e) { return std::abs(g - e) >= 0.25 * step; });
  EXPECT_EQ(t.size(), expected_frames);
  for (std::size_t k = 1; k < t.size(); ++k) {
    const double gap = t[k].unix_seconds - t[k - 1].unix_seconds;
    EXPECT_GE(gap, 0.25 * step);
    EXPECT_LE(gap, 1.25 * step + 1e-6);
  }
}

TEST(TimeSeriesDay, PolarDayIsTheWholeLocalDayAndPolarNightHasNoFrames) {
  const sky::Observer svalbard{78.2, 15.6, 0.0};
  const TimeSeries day = resolve_time_series(parse_time_spec("2026-06-21"), svalbard);
  EXPECT_NE(day.note.find("polar day"), std::string::npos);
  expect_clean(day.note);
  ASSERT_GE(day.instants.size(), 2u);
  // Local mean midnight to midnight: UTC midnight less 15.6°/15° h.
  const double start = sky::utc_from_civil(2026, 6, 21).unix_seconds - 15.6 / 15.0 * 3600.0;
  EXPECT_NEAR(day.instants.front().unix_seconds, start, 1e-6);
  EXPECT_NEAR(day.instants.back().unix_seconds, start + 86400.0, 1e-6);
  // Its start is 0.48 of a step off the grid: all 288 grid points inside, plus the ends.
  EXPECT_EQ(day.instants.size(), 86400.0 / kDefaultDayStepSeconds + 2);
  const TimeSeries night = resolve_time_series(parse_time_spec("2026-12-21"), svalbard);
  EXPECT_TRUE(night.instants.empty());
  EXPECT_NE(night.note.find("polar night"), std::string::npos);
  expect_clean(night.note);
  // The poles themselves (rise/set hour angle undefined) give the same answers.
  EXPECT_NE(resolve_time_series(parse_time_spec("2026-06-21"), sky::Observer{90, 0, 0}).note.find("polar day"),
            std::string::npos);
  EXPECT_NE(resolve_time_series(parse_time_spec("2026-06-21"), sky::Observer{-90, 0, 0}).note.find("polar night"),
            std::string::npos);
}

}  // namespace
}  // namespace skylit::shading
