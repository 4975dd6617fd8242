// IGC B records decoded by hand from the FAI/IGC spec's byte layout (chapter A4):
// B HHMMSS DDMMmmmN DDDMMmmmE V PPPPP GGGGG, then the I record's extension bytes.
#include "flight/igc_reader.h"

#include <gtest/gtest.h>

#include <sstream>

namespace skylit::flight {
namespace {

std::vector<Track> igc(const std::string& text) {
  std::istringstream in(text);
  return read_igc(in, "t.igc");
}

std::string error_of(const std::string& text) {
  try {
    igc(text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

constexpr double kDay0 = 1782000000.0;  // 2026-06-21T00:00:00Z (Python datetime)

TEST(IgcReader, DecodesBRecordsByTheSpecsLayout) {
  const auto tracks = igc(
      "AXXX001 logger\r\n"
      "HFDTEDATE:210626,01\r\n"
      "HFGIDGLIDERID:D-1234\r\n"
      "I023638FXA3940SIU\r\n"
      "B1000004812345N01101234EA024500248001203\r\n"
      "B1000014759999S00000001WV-0012-0003\r\n");
  ASSERT_EQ(tracks.size(), 1u);
  const Track& t = tracks[0];
  EXPECT_EQ(t.id, "D-1234");
  ASSERT_EQ(t.fixes.size(), 2u);
  const Fix& a = t.fixes[0];
  EXPECT_DOUBLE_EQ(a.time_s, kDay0 + 36000.0);
  EXPECT_NEAR(a.lat_deg, 48.0 + 12.345 / 60.0, 1e-12);
  EXPECT_NEAR(a.lon_deg, 11.0 + 1.234 / 60.0, 1e-12);
  EXPECT_TRUE(a.valid);
  ASSERT_TRUE(a.pressure && a.gnss);
  EXPECT_EQ(a.pressure->metres, 2450.0);
  EXPECT_EQ(a.pressure->datum, AltitudeDatum::pressure_isa);
  EXPECT_EQ(a.gnss->metres, 2480.0);
  EXPECT_EQ(a.gnss->datum, AltitudeDatum::wgs84_ellipsoid);  // spec: above the WGS84 ellipsoid
  ASSERT_EQ(a.extensions.size(), 2u);
  EXPECT_EQ(a.extensions[0].code, "FXA");
  EXPECT_EQ(a.extensions[0].value, "012");
  EXPECT_EQ(a.extensions[1].code, "SIU");
  EXPECT_EQ(a.extensions[1].value, "03");
  const Fix& b = t.fixes[1];
  EXPECT_NEAR(b.lat_deg, -(47.0 + 59.999 / 60.0), 1e-12);
  EXPECT_NEAR(b.lon_deg, -(0.001 / 60.0), 1e-15);
  EXPECT_FALSE(b.valid);
  EXPECT_EQ(b.pressure->metres, -12.0);
  EXPECT_EQ(b.gnss->metres, -3.0);
  EXPECT_TRUE(b.extensions.empty());  // the line ends before the extension bytes
}

TEST(IgcReader, OldDateHeaderMidnightWrapAndRepeatedDate) {
  const auto t = igc(
      "HFDTE210626\n"
      "B2359594812345N01101234EA0245002480\n"
      "B0000014812345N01101234EA0245002480\n"
      "HFDTEDATE:230626\n"
      "B0000004812345N01101234EA0245002480\n")[0];
  ASSERT_EQ(t.fixes.size(), 3u);
  EXPECT_DOUBLE_EQ(t.fixes[0].time_s, kDay0 + 86399.0);
  EXPECT_DOUBLE_EQ(t.fixes[1].time_s, kDay0 + 86401.0);      // wrapped into the 22nd
  EXPECT_DOUBLE_EQ(t.fixes[2].time_s, kDay0 + 2 * 86400.0);  // the new header's day
}

TEST(IgcReader, GeoidDeclarationAndUnrecordedChannels) {
  const auto t = igc(
      "HFDTE210626\nHFALGALTGPS:GEO\n"
      "B1000004812345N01101234EA0000002480\n"
      "B1000014812345N01101234EA0000002481\n")[0];
  EXPECT_EQ(t.fixes[0].gnss->datum, AltitudeDatum::geoid_msl);
  EXPECT_FALSE(t.fixes[0].pressure);  // 00000 throughout: no pressure sensor
}

TEST(IgcReader, OneLineErrorsNamingTheLine) {
  EXPECT_EQ(error_of(""), "t.igc: empty file");
  EXPECT_EQ(error_of("HFDTE210626\nLXXX comment\n"), "t.igc: no B records (fixes)");
  EXPECT_EQ(error_of("AXXX\nB1000004812345N01101234EA0245002480\n"), "t.igc:2: B record before any date header (HFDTE)");
  EXPECT_NE(error_of("HFDTE210626\nB1000054812345N01101234EA0245002480\nB1000024812345N01101234EA0245002480\n")
                .find("t.igc:3: time 2026-06-21T10:00:02Z runs backwards"),
            std::string::npos);
  EXPECT_NE(error_of("HFDTE210626\nB1000054812345N01101234EA0245002480\nB1000054812345N01101234EA0245002480\n").find("repeats"),
            std::string::npos);
  EXPECT_NE(error_of("HFDTE210626\nB1000009112345N01101234EA0245002480\n").find("t.igc:2: coordinates"), std::string::npos);
  EXPECT_NE(error_of("HFDTE210626\nB1000004865345N01101234EA0245002480\n").find("latitude"), std::string::npos);  // 65'
  EXPECT_NE(error_of("HFDTE210626\nB1000004812345N01101234EX0245002480\n").find("validity"), std::string::npos);
  EXPECT_NE(error_of("HFDTE310226\n").find("not a calendar date"), std::string::npos);
  EXPECT_NE(error_of("HFDTE210626\nB10000048\n").find("shorter than 35"), std::string::npos);
  EXPECT_NE(error_of(std::string("HFDTE21") + std::string(2, '\0') + "0626\n").find("binary"), std::string::npos);
  EXPECT_NE(error_of("HFDTE210626\n" + std::string(70000, 'B')).find("longer than"), std::string::npos);
}

}  // namespace
}  // namespace skylit::flight
