// The web-map tile grid (terrain/web_mercator.h) against independent values: the
// published WebMercatorQuad constants, hand arithmetic, and PROJ through GDAL's
// OGRCoordinateTransformation (which shares no code with our formulas).
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <numbers>

#include "terrain/dem_reader.h"
#include "terrain/web_mercator.h"
#include "terrain_test_util.h"

namespace skylit::terrain {
namespace {

// WebMercatorQuad's half width (OGC TMS 2.0 / gdal2tiles: 20037508.342789244).
constexpr double kHalfWorld = 20037508.342789244;

// PROJ's 4326 → 3857 (lon/lat order) and back.
class Proj {
 public:
  Proj() {
    geo_.importFromEPSG(4326);
    merc_.importFromEPSG(3857);
    geo_.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    merc_.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    fwd_.reset(OGRCreateCoordinateTransformation(&geo_, &merc_));
    inv_.reset(OGRCreateCoordinateTransformation(&merc_, &geo_));
  }
  MercatorPoint forward(double lon, double lat) const {
    double x = lon, y = lat;
    EXPECT_TRUE(fwd_->Transform(1, &x, &y));
    return {x, y};
  }
  LatLon inverse(double x, double y) const {
    EXPECT_TRUE(inv_->Transform(1, &x, &y));
    return {y, x};
  }

 private:
  OGRSpatialReference geo_, merc_;
  std::unique_ptr<OGRCoordinateTransformation> fwd_, inv_;
};

TEST(WebMercator, ConstantsMatchThePublishedGrid) {
  EXPECT_DOUBLE_EQ(kWebMercatorOriginShift, kHalfWorld);
  // The square world ends where y = π·R: φ = atan(sinh π).
  EXPECT_NEAR(kWebMercatorMaxLatitudeDeg, std::atan(std::sinh(std::numbers::pi)) * 180 / std::numbers::pi, 1e-13);
  EXPECT_NEAR(kWebMercatorMaxLatitudeDeg, 85.0511287798, 1e-10);
  // gdal2tiles' initialResolution = 2π·6378137 / 256 = 156543.03392804097 m.
  EXPECT_DOUBLE_EQ(pixel_size(0, 256), 156543.03392804097);
  EXPECT_DOUBLE_EQ(pixel_size(0, 512), 156543.03392804097 / 2);
  EXPECT_DOUBLE_EQ(pixel_size(10, 256), 156543.03392804097 / 1024);
  EXPECT_NEAR(ground_pixel_size(0, 60.0), 156543.03392804097 / 2, 1e-8);  // cos 60° = ½
  EXPECT_EQ(tiles_per_side(0), 1);
  EXPECT_EQ(tiles_per_side(12), 4096);
}

TEST(WebMercator, TileBoundsInMetres) {
  const MercatorBox z0 = tile_bounds({0, 0, 0});
  EXPECT_DOUBLE_EQ(z0.xmin, -kHalfWorld);
  EXPECT_DOUBLE_EQ(z0.xmax, kHalfWorld);
  EXPECT_DOUBLE_EQ(z0.ymin, -kHalfWorld);
  EXPECT_DOUBLE_EQ(z0.ymax, kHalfWorld);
  // 1/0/0 is the north-west quarter; 1/1/1 the south-east one (XYZ: y grows south).
  const MercatorBox nw = tile_bounds({1, 0, 0}), se = tile_bounds({1, 1, 1});
  EXPECT_DOUBLE_EQ(nw.xmin, -kHalfWorld);
  EXPECT_DOUBLE_EQ(nw.xmax, 0.0);
  EXPECT_DOUBLE_EQ(nw.ymin, 0.0);
  EXPECT_DOUBLE_EQ(nw.ymax, kHalfWorld);
  EXPECT_DOUBLE_EQ(se.xmin, 0.0);
  EXPECT_DOUBLE_EQ(se.ymax, 0.0);
  EXPECT_DOUBLE_EQ(se.ymin, -kHalfWorld);
  // 3/2/5: x from −S + 2·S/4 = −S/2 to −S/4; y from S − 6·S/4 = −S/2 to S − 5·S/4 = −S/4.
  const MercatorBox t = tile_bounds({3, 2, 5});
  EXPECT_NEAR(t.xmin, -kHalfWorld / 2, 1e-8);
  EXPECT_NEAR(t.xmax, -kHalfWorld / 4, 1e-8);
  EXPECT_NEAR(t.ymin, -kHalfWorld / 2, 1e-8);
  EXPECT_NEAR(t.ymax, -kHalfWorld / 4, 1e-8);
  EXPECT_THROW(tile_bounds({1, 2, 0}), std::invalid_argument);
  EXPECT_THROW(tile_bounds({31, 0, 0}), std::invalid_argument);
  EXPECT_THROW(pixel_size(3, 300), std::invalid_argument);
}

TEST(WebMercator, TileBoundsInDegrees) {
  const LonLatBox z0 = tile_lon_lat_bounds({0, 0, 0});
  EXPECT_NEAR(z0.west, -180.0, 1e-12);
  EXPECT_NEAR(z0.east, 180.0, 1e-12);
  EXPECT_NEAR(z0.north, 85.0511287798066, 1e-10);
  EXPECT_NEAR(z0.south, -85.0511287798066, 1e-10);
  // 2/1/1: lon −90…0; north edge at y = S/2, φ = atan(sinh(π/2)) = 66.51326044311186°.
  const LonLatBox t = tile_lon_lat_bounds({2, 1, 1});
  EXPECT_NEAR(t.west, -90.0, 1e-12);
  EXPECT_NEAR(t.east, 0.0, 1e-12);
  EXPECT_NEAR(t.north, 66.51326044311186, 1e-10);
  EXPECT_NEAR(t.south, 0.0, 1e-12);
  // Every corner of a few tiles against PROJ's inverse.
  const Proj proj;
  for (const TileId id : {TileId{5, 3, 11}, TileId{10, 175, 407}, TileId{13, 1407, 3263}, TileId{18, 200000, 1000}}) {
    const MercatorBox m = tile_bounds(id);
    const LonLatBox g = tile_lon_lat_bounds(id);
    const LatLon sw = proj.inverse(m.xmin, m.ymin), ne = proj.inverse(m.xmax, m.ymax);
    EXPECT_NEAR(g.west, sw.longitude_deg, 1e-10);
    EXPECT_NEAR(g.south, sw.latitude_deg, 1e-10);
    EXPECT_NEAR(g.east, ne.longitude_deg, 1e-10);
    EXPECT_NEAR(g.north, ne.latitude_deg, 1e-10);
  }
}

TEST(WebMercator, ProjectionMatchesProj) {
  const Proj proj;
  for (double lat : {-85.0, -60.5, -33.9, 0.0, 0.001, 34.32, 47.85, 66.0, 84.9})
    for (double lon : {-179.9, -118.15, 0.0, 7.3, 151.2}) {
      const MercatorPoint ours = lon_lat_to_mercator(lon, lat), theirs = proj.forward(lon, lat);
      EXPECT_NEAR(ours.x, theirs.x, 1e-6) << lon << ", " << lat;
      EXPECT_NEAR(ours.y, theirs.y, 1e-6) << lon << ", " << lat;
      const LatLon back = mercator_to_lon_lat(ours.x, ours.y);
      EXPECT_NEAR(back.latitude_deg, lat, 1e-11);
      EXPECT_NEAR(back.longitude_deg, lon, 1e-11);
    }
  // Latitudes beyond the square are clamped onto its edge.
  EXPECT_DOUBLE_EQ(clamp_latitude(89.0), kWebMercatorMaxLatitudeDeg);
  EXPECT_DOUBLE_EQ(clamp_latitude(-90.0), -kWebMercatorMaxLatitudeDeg);
  EXPECT_NEAR(lon_lat_to_mercator(0, 89.0).y, kHalfWorld, 1e-6);
}

TEST(WebMercator, TileAtAPoint) {
  // Big Tujunga's centre (118°08'57.22"W, 34°19'13.20"N) at z 13: x = ⌊(180 − 118.14923)/360 · 8192⌋
  // = ⌊1407.46⌋; y from PROJ's northing: ⌊(S − y)/(2S/8192)⌋.
  const Proj proj;
  const double lon = -(118 + 8 / 60.0 + 57.22 / 3600), lat = 34 + 19 / 60.0 + 13.20 / 3600;
  const MercatorPoint p = proj.forward(lon, lat);
  const int y_proj = static_cast<int>(std::floor((kHalfWorld - p.y) / (2 * kHalfWorld / 8192)));
  EXPECT_EQ(tile_at(lon, lat, 13), (TileId{13, 1407, y_proj}));
  EXPECT_EQ(y_proj, 3263);
  // Edges belong to the tile east / south of them.
  EXPECT_EQ(tile_at(0.0, 0.0, 1), (TileId{1, 1, 1}));
  EXPECT_EQ(tile_at(-180.0, 85.0511287798066, 4), (TileId{4, 0, 0}));
  EXPECT_EQ(tile_at(180.0, -89.0, 4), (TileId{4, 15, 15}));  // clamped onto the last tile
  EXPECT_EQ(tile_at(10.0, 89.9, 4).y, 0);
}

TEST(WebMercator, TilesCoveringABox) {
  // Exactly one tile's box selects only that tile (touching edges do not count).
  const TileId id{7, 21, 50};
  const MercatorBox b = tile_bounds(id);
  EXPECT_EQ(tiles_covering(b, 7), (TileRange{7, 21, 50, 21, 50}));
  // A box from the middle of 7/21/50 to the middle of 7/23/51.
  const double span = 2 * kHalfWorld / 128;
  const MercatorBox wide{b.xmin + span / 2, b.ymin - span / 2, b.xmin + 2.5 * span, b.ymax - span / 2};
  const TileRange r = tiles_covering(wide, 7);
  EXPECT_EQ(r, (TileRange{7, 21, 50, 23, 51}));
  EXPECT_EQ(r.count(), 6);
  EXPECT_TRUE(r.contains({7, 22, 51}));
  EXPECT_FALSE(r.contains({7, 24, 51}));
  // The whole world, and beyond it.
  EXPECT_EQ(tiles_covering(LonLatBox{-180, -90, 180, 90}, 3), (TileRange{3, 0, 0, 7, 7}));
  EXPECT_EQ(tiles_covering(MercatorBox{-3e7, -3e7, 3e7, 3e7}, 2), (TileRange{2, 0, 0, 3, 3}));
  EXPECT_TRUE(tiles_covering(MercatorBox{2.1e7, 0, 2.2e7, 1}, 2).empty());
  // A point-sized box selects the tile holding it.
  EXPECT_EQ(tiles_covering(MercatorBox{1, 1, 1, 1}, 1), (TileRange{1, 1, 0, 1, 0}));
  // The lon/lat box of Big Tujunga's corners at z 10 (PROJ-projected for the check).
  const Proj proj;
  const LonLatBox dem{-118.34573, 34.23167, -117.95312, 34.40898};
  const MercatorPoint sw = proj.forward(dem.west, dem.south), ne = proj.forward(dem.east, dem.north);
  const double s10 = 2 * kHalfWorld / 1024;
  const TileRange expect{10, static_cast<int>(std::floor((sw.x + kHalfWorld) / s10)),
                         static_cast<int>(std::floor((kHalfWorld - ne.y) / s10)),
                         static_cast<int>(std::floor((ne.x + kHalfWorld) / s10)),
                         static_cast<int>(std::floor((kHalfWorld - sw.y) / s10))};
  EXPECT_EQ(tiles_covering(dem, 10), expect);
}

TEST(WebMercator, TmsRowsFlip) {
  EXPECT_EQ(tms_y(0, 0), 0);
  EXPECT_EQ(tms_y(3, 0), 7);
  EXPECT_EQ(tms_y(3, 5), 2);
  EXPECT_EQ(tms_y(3, tms_y(3, 5)), 5);
}

TEST(WebMercator, NativeZoomOfBigTujunga) {
  const std::string path = std::string(SKYLIT_SHARED_DIR) + "/dem/big_tujunga_srtm30_utm11n.tif";
  SKYLIT_REQUIRE(testing::missing_file(path));
  const DemReadResult dem = read_dem(path);
  // 30 m UTM pixels; centre at 34°19'13.20"N (gdalinfo), cos φ = 0.82586.
  // 256 px: ground pixel = 156543.034 · 0.82586 / 2^z = 129282 m / 2^z:
  //   z 12: 31.56 m (coarser than 30 m), z 13: 15.78 m (finer) → native 13.
  // 512 px: half of that at each zoom → native 12 (15.78 m), z 11 is 31.56 m.
  EXPECT_EQ(native_zoom(dem.field, 256), 13);
  EXPECT_EQ(native_zoom(dem.field, 512), 12);
  EXPECT_EQ(default_zoom_range(13), (ZoomRange{8, 13}));
  EXPECT_EQ(default_zoom_range(3), (ZoomRange{0, 3}));
}

TEST(WebMercator, NativeZoomRule) {
  // A 4326 grid at the equator whose pixel is exactly z 5's ground pixel: native 5, and
  // a hair coarser still 5, a hair finer 6.
  HeightField f(8, 8, 1.0);
  f.georef = skylit::terrain::testing::epsg_georef(4326, {-0.1, 0.025, 0, 0.1, 0, -0.025});
  f.georef.geographic = true;
  const double z5 = 156543.03392804097 / 32;  // cos 0 = 1
  for (auto [spacing, zoom] : {std::pair{z5, 5}, std::pair{z5 * 1.001, 5}, std::pair{z5 * 0.999, 6}}) {
    f.dy = spacing;
    f.dx_per_row.assign(8, spacing);
    EXPECT_EQ(native_zoom(f), zoom) << spacing;
  }
  // At 60°N the same zoom's ground pixel is half as large (Mercator scale 1/cos φ = 2):
  // a grid of z5/2 metres is still native 5 (without the cos φ it would be 6).
  f.georef.geotransform = {-0.1, 0.025, 0, 60.1, 0, -0.025};
  f.dy = z5 / 2;
  f.dx_per_row.assign(8, z5 / 2);
  EXPECT_EQ(native_zoom(f), 5);
  f.georef.geotransform = {-0.1, 0.025, 0, 0.1, 0, -0.025};
  // Non-square pixels: the finer axis decides.
  f.dy = z5 * 4;
  f.dx_per_row.assign(8, z5);
  EXPECT_EQ(native_zoom(f), 5);
  // No CRS: a one-line error.
  f.georef.crs_wkt.clear();
  try {
    native_zoom(f);
    FAIL() << "no exception";
  } catch (const DemError& e) {
    EXPECT_NE(std::string(e.what()).find("no CRS"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
  }
}

// The DEM's box: beside the antimeridian as it lies; across it (in degrees or projected)
// west in −180…180° and east past 180°, where tiles_covering goes on into the next
// copy of the world and wrap_tile folds the columns back; stored past ±180°, moved
// into −180…180°; the whole world spans the grid once.
TEST(WebMercator, DemBoundsAcrossTheAntimeridianRunPast180) {
  auto geographic = [](double west, double north, double step, int width, int height) {
    HeightField f(width, height, 1000.0);
    f.georef = skylit::terrain::testing::epsg_georef(4326, {west, step, 0, north, 0, -step});
    f.georef.geographic = true;
    return f;
  };
  auto expect_box = [](const LonLatBox& b, double west, double east) {
    EXPECT_NEAR(b.west, west, 1e-9);
    EXPECT_NEAR(b.east, east, 1e-9);
  };
  expect_box(dem_lon_lat_bounds(geographic(179.0, 10.0, 0.1, 9, 4)), 179.0, 179.9);
  expect_box(dem_lon_lat_bounds(geographic(-179.9, 10.0, 0.1, 9, 4)), -179.9, -179.0);
  expect_box(dem_lon_lat_bounds(geographic(-180.0, 80.0, 10.0, 36, 16)), -180.0, 180.0);
  expect_box(dem_lon_lat_bounds(geographic(179.9, 10.0, 0.05, 4, 4)), 179.9, 180.1);   // stored across 180°
  expect_box(dem_lon_lat_bounds(geographic(-180.1, 10.0, 0.05, 4, 4)), 179.9, 180.1);  // stored across −180°
  expect_box(dem_lon_lat_bounds(geographic(180.5, 10.0, 0.1, 4, 4)), -179.5, -179.1);  // stored past 180°
  expect_box(dem_lon_lat_bounds(geographic(-181.0, 10.0, 0.1, 4, 4)), 179.0, 179.4);

  // UTM zone 1 N (central meridian 177° W): at 45° N, 3° west of it lies ≈ 236 km west of
  // the false easting, so eastings 262–266 km straddle 180°; at the false easting, 177° W.
  HeightField utm(64, 64, 60.0);
  utm.georef = skylit::terrain::testing::epsg_georef(32601, {262000, 60, 0, 5003840, 0, -60});
  const LonLatBox across = dem_lon_lat_bounds(utm);
  EXPECT_LT(across.west, 180.0);
  EXPECT_GT(across.east, 180.0);
  EXPECT_LT(across.east - across.west, 0.1);
  utm.georef = skylit::terrain::testing::epsg_georef(32601, {500000, 60, 0, 5003840, 0, -60});
  const LonLatBox at_cm = dem_lon_lat_bounds(utm);
  // Its centre, 1.92 km east of 177° W: 1.92 / (111.32 · cos 45°) = 0.0244°.
  EXPECT_NEAR(0.5 * (at_cm.west + at_cm.east), -177.0 + 0.0244, 0.005);

  // z 3: 179.9° E is in column 7, 179.9° W (180.1°) in column 0 of the next world, 8.
  const HeightField crossing = geographic(179.9, 10.0, 0.05, 4, 4);
  const TileRange r = tiles_covering(dem_mercator_bounds(crossing), 3);
  EXPECT_EQ(r.x0, 7);
  EXPECT_EQ(r.x1, 8);
  EXPECT_EQ(wrap_tile({3, 8, r.y0}), (TileId{3, 0, r.y0}));
  EXPECT_EQ(wrap_tile({3, 7, r.y0}), (TileId{3, 7, r.y0}));
  // Never more than one world of columns, whatever the box.
  const TileRange wide = tiles_covering(MercatorBox{-1e7, 0, 5e7, 1}, 2);
  EXPECT_EQ(wide.columns(), 4);
}

}  // namespace
}  // namespace skylit::terrain
