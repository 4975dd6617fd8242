// ISO 8601 as the track formats write it, against POSIX times computed independently
// (Python's datetime: 2026-06-21T10:00:00Z = 1782036000, 2024-02-29T12:30:15Z = 1709209815).
#include "flight/track_time.h"

#include <gtest/gtest.h>

namespace skylit::flight {
namespace {

TEST(TrackTime, ParsesZoneOffsetsAndFractions) {
  EXPECT_DOUBLE_EQ(*parse_iso8601("2026-06-21T10:00:00Z"), 1782036000.0);
  EXPECT_DOUBLE_EQ(*parse_iso8601("2026-06-21T12:00:00+02:00"), 1782036000.0);
  EXPECT_DOUBLE_EQ(*parse_iso8601("2026-06-21T05:30:00-0430"), 1782036000.0);
  EXPECT_DOUBLE_EQ(*parse_iso8601("2024-02-29T12:30:15.250Z"), 1709209815.25);
  EXPECT_DOUBLE_EQ(*parse_iso8601("2024-02-29 12:30:15", true), 1709209815.0);
  EXPECT_DOUBLE_EQ(*parse_iso8601("1970-01-01T00:00:00Z"), 0.0);
}

TEST(TrackTime, RejectsWhatIsNotATime) {
  EXPECT_FALSE(parse_iso8601("2024-02-29T12:30:15"));  // no zone, not assumed
  EXPECT_FALSE(parse_iso8601("2023-02-29T12:30:15Z"));  // not a leap year
  EXPECT_FALSE(parse_iso8601("2024-13-01T00:00:00Z"));
  EXPECT_FALSE(parse_iso8601("2024-01-01T24:00:00Z"));
  EXPECT_FALSE(parse_iso8601("2024-01-01T10:00:00Zjunk"));
  EXPECT_FALSE(parse_iso8601("2024-01-01"));
  EXPECT_FALSE(parse_iso8601(""));
}

TEST(TrackTime, FormatsUtcWithMillisecondsOnlyWhenPresent) {
  EXPECT_EQ(format_iso8601(1782036000.0), "2026-06-21T10:00:00Z");
  EXPECT_EQ(format_iso8601(1709209815.25), "2024-02-29T12:30:15.250Z");
  EXPECT_EQ(format_iso8601(-1.0), "1969-12-31T23:59:59Z");
}

}  // namespace
}  // namespace skylit::flight
