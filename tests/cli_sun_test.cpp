// `skylit sun` end to end: runs the built binary, parses its JSON, checks the
// NREL SPA example and polar night, and one-line errors with non-zero exit.
#include "cli_test_util.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

using skylit::testing::count_lines;
using skylit::testing::run_skylit;

TEST(CliSun, JsonForTheSpaExample) {
  // NREL SPA example (Reda & Andreas 2004): zenith 50.11162°, azimuth 194.34024°
  // at 820 mbar, 11 °C; sunrise 06:12:43 local (UTC−7).
  const auto r = run_skylit(
      "sun --lat 39.742476 --lon -105.1786 --height 1830.14 --pressure 820 --temperature 11 "
      "--time 2003-10-17T12:30:30-07:00 --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);  // throws unless exactly one JSON value
  ASSERT_TRUE(j.is_object());
  EXPECT_EQ(j.size(), 6u);
  // The CLI uses the modelled ΔT (64.4 s, not the paper's 67 s): 1e-4° still holds.
  EXPECT_NEAR(j.at("azimuth_deg").get<double>(), 194.340241, 1e-4);
  EXPECT_NEAR(90.0 - j.at("apparent_elevation_deg").get<double>(), 50.111622, 1e-4);
  EXPECT_NEAR(j.at("elevation_deg").get<double>(), 39.872046, 1e-4);
  EXPECT_EQ(j.at("sunrise"), "2003-10-17T13:12:43Z");
  EXPECT_EQ(j.at("solar_noon"), "2003-10-17T18:46:05Z");
  // This local day's sunset is the next UTC date.
  EXPECT_EQ(j.at("sunset").get<std::string>().substr(0, 14), "2003-10-18T00:");
}

TEST(CliSun, PolarNightGivesNulls) {
  const auto r = run_skylit("sun --lat 78.22 --lon 15.65 --time 2026-12-21T12:00:00Z --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j.at("sunrise").is_null());
  EXPECT_TRUE(j.at("sunset").is_null());
  EXPECT_TRUE(j.at("solar_noon").is_string());
  EXPECT_LT(j.at("elevation_deg").get<double>(), 0.0);
}

TEST(CliSun, UtcOffsetsGiveTheSameAnswer) {
  const auto z = run_skylit("sun --lat 47.37 --lon 8.54 --time 2026-06-21T09:30:00Z --json");
  const auto plus = run_skylit("sun --lat 47.37 --lon 8.54 --time 2026-06-21T11:30:00+02:00 --json");
  ASSERT_EQ(z.status, 0);
  EXPECT_EQ(z.out, plus.out);
}

TEST(CliSun, TextOutputNamesEveryQuantity) {
  const auto r = run_skylit("sun --lat 47.37 --lon 8.54 --time 2026-06-21T09:30:00Z");
  ASSERT_EQ(r.status, 0) << r.out;
  for (const char* key : {"azimuth", "elevation", "apparent elevation", "sunrise", "solar noon", "sunset"})
    EXPECT_NE(r.out.find(key), std::string::npos) << key;
}

TEST(CliSun, ErrorsAreOneLineWithNonZeroExit) {
  struct Case {
    const char* args;
    const char* says;
  };
  for (const Case& c : {
           Case{"sun --lat 95 --lon 0 --time 2026-06-21T09:30:00Z", "--lat"},
           Case{"sun --lat -90.5 --lon 0 --time 2026-06-21T09:30:00Z", "--lat"},
           Case{"sun --lat 10 --lon 181 --time 2026-06-21T09:30:00Z", "--lon"},
           Case{"sun --lat 10 --lon -180.01 --time 2026-06-21T09:30:00Z", "--lon"},
           Case{"sun --lat 10 --lon 0 --time yesterday", "invalid time"},
           Case{"sun --lat 10 --lon 0 --time 2026-13-21T09:30:00Z", "month"},
           Case{"sun --lat 10 --lon 0 --time 2026-06-21T09:30:00", "append Z"},
       }) {
    const auto r = run_skylit(std::string(c.args) + " --json", true);
    EXPECT_NE(r.status, 0) << c.args;
    EXPECT_EQ(count_lines(r.out), 1) << c.args << "\n" << r.out;
    EXPECT_NE(r.out.find(c.says), std::string::npos) << c.args << "\n" << r.out;
  }
}
