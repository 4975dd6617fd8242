// read_track_file: format detection, the small samples of every format, the shipped
// sample glider flight (decoded by hand from its B records, placed over the synthetic
// scene), and the one-line errors for files that are not tracks.
#include "flight/altitude.h"
#include "flight/lon_lat_projection.h"
#include "flight/track_reader.h"
#include "flight/track_sampler.h"

#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace skylit::flight {
namespace {

const std::string kData = std::string(SKYLIT_SOURCE_DIR) + "/tests/data/tracks/";
const std::string kSample = std::string(SKYLIT_SOURCE_DIR) + "/data/tracks/sample_glider.igc";

std::string error_of(const std::string& path) {
  try {
    read_track_file(path);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

struct TempFile {
  std::string path;
  TempFile(const std::string& name, const std::string& content)
      : path((std::filesystem::temp_directory_path() / ("skylit_" + std::to_string(::getpid()) + "_" + name)).string()) {
    std::ofstream(path, std::ios::binary) << content;
  }
  ~TempFile() { std::filesystem::remove(path); }
};

TEST(TrackReader, DetectsFormatsByExtensionAndContent) {
  EXPECT_EQ(format_from_extension("a/B.IGC"), TrackFormat::igc);
  EXPECT_EQ(format_from_extension("x.kml"), TrackFormat::kml);
  EXPECT_FALSE(format_from_extension("x.txt"));
  EXPECT_EQ(sniff_track_format("<?xml version=\"1.0\"?>\n<!-- c --><gpx version=\"1.1\">"), TrackFormat::gpx);
  EXPECT_EQ(sniff_track_format("\xEF\xBB\xBF<kml xmlns=\"x\">"), TrackFormat::kml);
  EXPECT_EQ(sniff_track_format("AXCS123\r\nHFDTE010101\r\n"), TrackFormat::igc);
  EXPECT_EQ(sniff_track_format("time,icao24,lat,lon\n"), TrackFormat::csv);
  EXPECT_EQ(sniff_track_format("Altitude,Lat,Lon,time\n"), TrackFormat::csv);
  EXPECT_FALSE(sniff_track_format("<html>"));
  EXPECT_FALSE(sniff_track_format("hello"));
  // Content decides when the extension does not.
  TempFile t("track.txt", "time,lat,lon\n1,2,3\n");
  EXPECT_EQ(read_track_file(t.path)[0].format, TrackFormat::csv);
}

TEST(TrackReader, ReadsTheSmallSamplesOfEveryFormat) {
  const auto gpx = read_track_file(kData + "tiny.gpx");
  ASSERT_EQ(gpx.size(), 1u);
  EXPECT_EQ(gpx[0].fixes.size(), 3u);
  EXPECT_DOUBLE_EQ(gpx[0].fixes[2].time_s, 1782036002.0);
  const auto kml = read_track_file(kData + "tiny.kml");
  ASSERT_EQ(kml.size(), 1u);
  EXPECT_DOUBLE_EQ(kml[0].fixes[2].time_s, 1782036002.5);
  EXPECT_EQ(read_track_file(kData + "tiny_opensky.csv").size(), 2u);
  const auto plain = read_track_file(kData + "tiny_plain.csv");
  EXPECT_DOUBLE_EQ(plain[0].fixes[1].time_s, 1782036001.0);
}

TEST(TrackReader, SampleGliderFlightStaysOverTheSyntheticScene) {
  const auto tracks = read_track_file(kSample);
  ASSERT_EQ(tracks.size(), 1u);
  const Track& t = tracks[0];
  EXPECT_EQ(t.id, "D-KSKY");
  ASSERT_EQ(t.fixes.size(), 601u);
  // First B record: B100000 4654618N 00742786E A 02765 02800.
  EXPECT_DOUBLE_EQ(t.fixes[0].time_s, 1782036000.0);
  EXPECT_NEAR(t.fixes[0].lat_deg, 46 + 54.618 / 60, 1e-12);
  EXPECT_NEAR(t.fixes[0].lon_deg, 7 + 42.786 / 60, 1e-12);
  EXPECT_EQ(t.fixes[0].pressure->metres, 2765.0);
  EXPECT_EQ(t.fixes[0].gnss->metres, 2800.0);
  EXPECT_DOUBLE_EQ(t.fixes.back().time_s, 1782036600.0);
  EXPECT_EQ(std::count_if(t.fixes.begin(), t.fixes.end(), [](const Fix& f) { return !f.valid; }), 20);

  OGRSpatialReference utm;
  ASSERT_EQ(utm.importFromEPSG(32632), OGRERR_NONE);
  char* wkt = nullptr;
  utm.exportToWkt(&wkt);
  const LonLatToCrs project(wkt);
  CPLFree(wkt);
  const AltitudeResolver gnss({AltitudeSource::gnss});
  const TrackSampler s(
      t, [&](double lon, double lat) { return project(lon, lat); },
      [&](const Fix& f, double x, double y) { return gnss.height(f, x, y); });
  EXPECT_EQ(s.fixes().size(), 581u);
  for (const PlacedFix& f : s.fixes()) {
    EXPECT_GT(f.position.x, 400000.0);
    EXPECT_LT(f.position.x, 415360.0);
    EXPECT_GT(f.position.y, 5184640.0);
    EXPECT_LT(f.position.y, 5200000.0);
    EXPECT_GT(f.position.z, 2400.0);  // above the scene's 2200 m peaks
    EXPECT_LT(f.position.z, 2900.0);
  }
  EXPECT_FALSE(s.pose_at(1782036000.0 + 350));  // inside the V stretch
  // The first thermal turns left, the second right (the generator's legs).
  EXPECT_LT(s.pose_at(1782036000.0 + 200)->attitude.bank_deg, -15.0);
  EXPECT_GT(s.pose_at(1782036000.0 + 480)->attitude.bank_deg, 15.0);
}

TEST(TrackReader, FilesThatAreNotTracksFailInOneLine) {
  EXPECT_EQ(error_of("/nonexistent/x.igc"), "/nonexistent/x.igc: cannot open (No such file or directory)");
  EXPECT_EQ(error_of(std::filesystem::temp_directory_path().string()),
            std::filesystem::temp_directory_path().string() + ": is a directory, not a track file");
  TempFile empty("empty.igc", "");
  EXPECT_EQ(error_of(empty.path), empty.path + ": empty file");
  TempFile binary("bin.gpx", std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16));
  EXPECT_EQ(error_of(binary.path), binary.path + ": binary content, not a track file");
  {  // A sparse 300 MiB GPX is refused before it is read.
    TempFile big("big.gpx", "<gpx>" + std::string(8192, ' '));  // text where the sniffing looks
    std::filesystem::resize_file(big.path, 300u << 20);
    EXPECT_EQ(error_of(big.path), big.path + ": larger than 256 MiB, too large to parse as XML");
  }
  TempFile unknown("notes.txt", "just some words\n");
  EXPECT_NE(error_of(unknown.path).find("not a track file this reads"), std::string::npos);
}

}  // namespace
}  // namespace skylit::flight
