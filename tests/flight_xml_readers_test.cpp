// GPX trkpt and KML gx:Track read against the values written into the documents, with
// the datums their specifications give (GPX ele: mean sea level; KML absolute: sea level,
// relativeToGround: above the ground, clampToGround: on it).
#include "flight/gpx_reader.h"
#include "flight/kml_reader.h"

#include <gtest/gtest.h>

#include <sstream>

namespace skylit::flight {
namespace {

template <class Reader>
std::string error_of(Reader read, const std::string& text) {
  std::istringstream in(text);
  try {
    read(in, "f");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

constexpr double k10h = 1782036000.0;  // 2026-06-21T10:00:00Z

TEST(GpxReader, TrackPointsWithElevationAndZonedTimes) {
  std::istringstream in(R"(<?xml version="1.0"?>
<gpx version="1.1" creator="t" xmlns="http://www.topografix.com/GPX/1/1">
  <trk><name>walk</name>
    <trkseg>
      <trkpt lat="46.5" lon="7.25"><ele>2401.5</ele><time>2026-06-21T10:00:00Z</time></trkpt>
      <trkpt lat="46.5001" lon="7.2502"><time>2026-06-21T12:00:01.5+02:00</time></trkpt>
    </trkseg>
    <trkseg>
      <trkpt lat="-46.5" lon="-7.25"><ele>-3</ele><time>2026-06-21T10:01:00Z</time></trkpt>
    </trkseg>
  </trk>
</gpx>)");
  const auto tracks = read_gpx(in, "f.gpx");
  ASSERT_EQ(tracks.size(), 1u);
  const Track& t = tracks[0];
  EXPECT_EQ(t.id, "walk");
  ASSERT_EQ(t.fixes.size(), 3u);
  EXPECT_DOUBLE_EQ(t.fixes[0].lat_deg, 46.5);
  EXPECT_DOUBLE_EQ(t.fixes[0].lon_deg, 7.25);
  EXPECT_DOUBLE_EQ(t.fixes[0].time_s, k10h);
  ASSERT_TRUE(t.fixes[0].stated);
  EXPECT_DOUBLE_EQ(t.fixes[0].stated->metres, 2401.5);
  EXPECT_EQ(t.fixes[0].stated->datum, AltitudeDatum::geoid_msl);
  EXPECT_DOUBLE_EQ(t.fixes[1].time_s, k10h + 1.5);
  EXPECT_FALSE(t.fixes[1].stated);
  EXPECT_DOUBLE_EQ(t.fixes[2].stated->metres, -3.0);
}

TEST(GpxReader, ErrorsNameTheLine) {
  EXPECT_EQ(error_of(read_gpx, "<gpx><trk><trkseg>\n<trkpt lat=\"1\" lon=\"2\"/></trkseg></trk></gpx>"),
            "f:2: trkpt without <time>");
  EXPECT_EQ(error_of(read_gpx, "<gpx>\n<trk><trkseg><trkpt lat=\"95\" lon=\"2\"><time>2026-06-21T10:00:00Z</time></trkpt>"
                               "</trkseg></trk></gpx>").substr(0, 17),
            "f:2: coordinates ");
  EXPECT_EQ(error_of(read_gpx, "<gpx><wpt lat=\"1\" lon=\"2\"/></gpx>"), "f: no track points (no <trk>/<trkseg>/<trkpt>)");
  EXPECT_NE(error_of(read_gpx, "<gpx>\n<trk>").find("f:2: not well-formed XML"), std::string::npos);
  EXPECT_EQ(error_of(read_gpx, "<kml/>"), "f: not a GPX file (root element is not <gpx>)");
  EXPECT_EQ(error_of(read_gpx, "  \n"), "f: empty file");
  EXPECT_NE(error_of(read_gpx, "<gpx><trk><trkseg><trkpt lat=\"1\" lon=\"2\"><time>2026-06-21T10:00:05Z</time></trkpt>\n"
                               "<trkpt lat=\"1\" lon=\"2\"><time>2026-06-21T10:00:04Z</time></trkpt></trkseg></trk></gpx>")
                .find("f:2: time 2026-06-21T10:00:04Z runs backwards"),
            std::string::npos);
}

const char* kKml = R"(<?xml version="1.0" encoding="UTF-8"?>
<kml xmlns="http://www.opengis.net/kml/2.2" xmlns:gx="http://www.google.com/kml/ext/2.2">
<Document>
  <Placemark><name>glider</name>
    <gx:Track>
      <altitudeMode>absolute</altitudeMode>
      <when>2026-06-21T10:00:00Z</when>
      <when>2026-06-21T10:00:01Z</when>
      <gx:coord>7.25 46.5 2500.5</gx:coord>
      <gx:coord>7.2501 46.5002 2501</gx:coord>
    </gx:Track>
  </Placemark>
  <Placemark><name>relative</name>
    <gx:Track><altitudeMode>relativeToGround</altitudeMode>
      <when>2026-06-21T10:00:00Z</when><gx:coord>7 46 120</gx:coord></gx:Track>
  </Placemark>
  <Placemark><name>clamped</name>
    <gx:Track><when>2026-06-21T10:00:00Z</when><gx:coord>7 46 999</gx:coord></gx:Track>
  </Placemark>
</Document>
</kml>)";

TEST(KmlReader, PairsWhenWithCoordAndKeepsTheAltitudeMode) {
  std::istringstream in(kKml);
  const auto tracks = read_kml(in, "f.kml");
  ASSERT_EQ(tracks.size(), 3u);
  const Track& t = tracks[0];
  EXPECT_EQ(t.id, "glider");
  ASSERT_EQ(t.fixes.size(), 2u);
  EXPECT_DOUBLE_EQ(t.fixes[1].time_s, k10h + 1.0);
  EXPECT_DOUBLE_EQ(t.fixes[1].lon_deg, 7.2501);  // gx:coord is lon lat alt
  EXPECT_DOUBLE_EQ(t.fixes[1].lat_deg, 46.5002);
  EXPECT_DOUBLE_EQ(t.fixes[0].stated->metres, 2500.5);
  EXPECT_EQ(t.fixes[0].stated->datum, AltitudeDatum::geoid_msl);
  EXPECT_EQ(tracks[1].fixes[0].stated->datum, AltitudeDatum::above_ground);
  EXPECT_DOUBLE_EQ(tracks[1].fixes[0].stated->metres, 120.0);
  EXPECT_EQ(tracks[2].fixes[0].stated->datum, AltitudeDatum::above_ground);  // clampToGround: KML's default
  EXPECT_DOUBLE_EQ(tracks[2].fixes[0].stated->metres, 0.0);
}

TEST(KmlReader, Errors) {
  EXPECT_NE(error_of(read_kml, "<kml><Placemark><gx:Track>\n<when>2026-06-21T10:00:00Z</when></gx:Track></Placemark></kml>")
                .find("1 <when> but 0 <gx:coord>"),
            std::string::npos);
  EXPECT_NE(error_of(read_kml, "<kml><gx:Track><when>2026-06-21T10:00:00Z</when>\n<gx:coord>7 x 1</gx:coord></gx:Track></kml>")
                .find("f:2: <gx:coord> '7 x 1' is not 'lon lat [alt]'"),
            std::string::npos);
  EXPECT_NE(error_of(read_kml, "<kml><gx:Track><altitudeMode>relativeToSeaFloor</altitudeMode></gx:Track></kml>").find("relativeToSeaFloor"),
            std::string::npos);
  EXPECT_EQ(error_of(read_kml, "<kml><Placemark><LineString/></Placemark></kml>"),
            "f: no track points (no <gx:Track> with <when> and <gx:coord>)");
}

}  // namespace
}  // namespace skylit::flight
