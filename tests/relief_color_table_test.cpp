// Colour-table parsing and the colour of a height, against hand-computed values of
// gdaldem's rules (colour_table.h, color_relief.h).
#include "shading/relief/color_relief.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace {

using skylit::relief::ColorSelection;
using skylit::relief::parse_color_table;
using skylit::relief::SourceInfo;

skylit::relief::ColorTable parse(const std::string& text, SourceInfo info = {}) {
  std::istringstream in(text);
  return parse_color_table(in, "t.txt", info);
}

std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(ReliefColorTable, SeparatorsNamesAndSorting) {
  const auto t = parse("# c\n/ also a comment\n\n300:white\n100,1,2,3\n200\t4 5 6 7\n");
  ASSERT_EQ(t.entries.size(), 3u);
  EXPECT_EQ(t.entries[0].value, 100.0);
  EXPECT_EQ(t.entries[0].a, 255);
  EXPECT_EQ(t.entries[1].a, 7);
  EXPECT_EQ(t.entries[2].r, 255);
}

TEST(ReliefColorTable, PercentagesOfTheRange) {
  const auto t = parse("0% 0 0 0\n25% 1 1 1\n100% 2 2 2\n", {std::nullopt, [] { return std::pair(100.0, 500.0); }});
  EXPECT_EQ(t.entries[1].value, 200.0);  // 100 + 0.25·400
  EXPECT_EQ(t.entries[2].value, 500.0);
}

TEST(ReliefColorTable, InterpolationRoundsLikeGdaldem) {
  const auto t = parse("0 0 0 0\n100 255 10 1\n");
  // 0.45 + 0 + 0.5·255 = 127.95 → 127; 0.45 + 5 → 5; 0.45 + 0.5 = 0.95 → 0.
  const auto c = skylit::relief::color_at(t, 50.0, ColorSelection::Interpolate);
  EXPECT_EQ(c[0], 127);
  EXPECT_EQ(c[1], 5);
  EXPECT_EQ(c[2], 0);
  EXPECT_EQ(c[3], 255);
  // Beyond the ends: the end colours.
  EXPECT_EQ(skylit::relief::color_at(t, -5.0, ColorSelection::Interpolate)[0], 0);
  EXPECT_EQ(skylit::relief::color_at(t, 500.0, ColorSelection::Interpolate)[0], 255);
  // Nearest: 60 is nearer 100; exact: 50 is no entry → transparent black.
  EXPECT_EQ(skylit::relief::color_at(t, 60.0, ColorSelection::NearestEntry)[0], 255);
  EXPECT_EQ(skylit::relief::color_at(t, 50.0, ColorSelection::ExactEntry)[3], 0);
}

TEST(ReliefColorTable, NodataKeepsItsOwnColour) {
  const auto t = parse("nv 9 9 9\n0 0 0 0\n100 200 200 200\n", {-50.0, {}});
  // An entry just above nodata copies 0's colour, so −49 is not mixed with nodata's grey.
  EXPECT_EQ(skylit::relief::color_at(t, -50.0, ColorSelection::Interpolate)[0], 9);
  EXPECT_EQ(skylit::relief::color_at(t, -49.0, ColorSelection::Interpolate)[0], 0);
}

TEST(ReliefColorTable, CptSlicesAndNodata) {
  const auto t = parse("# COLOR_MODEL = RGB\n0 0 0 255 10 0 255 0\nB 0 0 0\nF 1 1 1\nN 7 7 7\n", {-1.0, {}});
  ASSERT_EQ(t.entries.size(), 4u);  // nodata, its guard above, 0, 10
  EXPECT_EQ(t.entries[0].value, -1.0);
  EXPECT_EQ(t.entries[0].r, 7);
}

TEST(ReliefColorTable, BadLinesNameTheLine) {
  EXPECT_EQ(error_of("1 0 0 0\n2 0 0\n").substr(0, 8), "t.txt:2:");  // "0" is no colour name
  EXPECT_EQ(error_of("# x\n1 2 3 x\n").substr(0, 8), "t.txt:2:");
  EXPECT_EQ(error_of("150% 1 2 3\n").substr(0, 8), "t.txt:1:");
  EXPECT_EQ(error_of("1 300 2 3\n").substr(0, 8), "t.txt:1:");
  EXPECT_EQ(error_of("5\n").substr(0, 8), "t.txt:1:");
  EXPECT_NE(error_of("# only comments\n").find("no colour entries"), std::string::npos);
}

}  // namespace
