// DEM reader: validation errors on synthetic rasters, unit/scale handling, voids,
// mosaics, and metric spacing of the real DEMs against independent formulas.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "terrain/dem_reader.h"
#include "terrain_test_util.h"

namespace skylit::terrain {
namespace {

using testing::make_raster;
using testing::RasterSpec;
using testing::ramp;
using testing::ScratchDir;
using testing::shared_dem;

// The exception message, which must be one line.
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const DemError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    return m;
  }
  ADD_FAILURE() << "no DemError thrown";
  return {};
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

TEST(TerrainReader, MissingFile) {
  ScratchDir dir;
  const auto m = error_of([&] { read_dem(dir.file("nope.tif")); });
  EXPECT_TRUE(contains(m, "does not exist")) << m;
}

TEST(TerrainReader, CorruptFile) {
  ScratchDir dir;
  std::ofstream(dir.file("bad.tif")) << "this is not a TIFF at all";
  const auto m = error_of([&] { read_dem(dir.file("bad.tif")); });
  EXPECT_TRUE(contains(m, "cannot open DEM")) << m;
}

TEST(TerrainReader, TruncatedTiff) {
  ScratchDir dir;
  RasterSpec s;
  s.width = s.height = 64;
  s.values = ramp(64, 64, 100, 1, 1);
  make_raster(dir.file("t.tif"), s);
  testing::fs::resize_file(dir.file("t.tif"), testing::fs::file_size(dir.file("t.tif")) / 2);
  EXPECT_THROW(read_dem(dir.file("t.tif")), DemError);
}

TEST(TerrainReader, VectorIsNotARaster) {
  ScratchDir dir;
  std::ofstream(dir.file("v.geojson"))
      << R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{},)"
      << R"("geometry":{"type":"Point","coordinates":[1,2]}}]})";
  const auto m = error_of([&] { read_dem(dir.file("v.geojson")); });
  EXPECT_TRUE(contains(m, "not a raster")) << m;
}

TEST(TerrainReader, TooSmall) {
  ScratchDir dir;
  for (auto [w, h] : {std::pair{1, 1}, std::pair{1, 7}, std::pair{7, 1}}) {
    RasterSpec s;
    s.width = w;
    s.height = h;
    make_raster(dir.file("s.tif"), s);
    const auto m = error_of([&] { read_dem(dir.file("s.tif")); });
    EXPECT_TRUE(contains(m, "at least 2×2")) << m;
  }
}

TEST(TerrainReader, AllNodata) {
  ScratchDir dir;
  RasterSpec s;
  s.type = GDT_Int16;
  s.nodata = -32768;
  s.values.assign(16, -32768);
  make_raster(dir.file("a.tif"), s);
  const auto m = error_of([&] { read_dem(dir.file("a.tif")); });
  EXPECT_TRUE(contains(m, "every pixel is nodata")) << m;
}

TEST(TerrainReader, NanIsNodataInfIsError) {
  ScratchDir dir;
  RasterSpec s;
  s.values = ramp(4, 4, 100, 1, 0);
  s.values[5] = std::nan("");
  make_raster(dir.file("n.tif"), s);
  auto r = read_dem(dir.file("n.tif"));
  EXPECT_EQ(r.nodata_count, 1u);
  EXPECT_EQ(r.field.valid[5], 0);
  EXPECT_TRUE(std::isfinite(r.field.heights[5]));
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_TRUE(contains(r.warnings.back(), "NaN")) << r.warnings.back();

  s.nodata = std::nan("");  // declared: no warning
  make_raster(dir.file("n2.tif"), s);
  r = read_dem(dir.file("n2.tif"));
  EXPECT_EQ(r.nodata_count, 1u);
  EXPECT_TRUE(r.warnings.empty());

  s.nodata.reset();
  s.values[5] = INFINITY;
  make_raster(dir.file("i.tif"), s);
  const auto m = error_of([&] { read_dem(dir.file("i.tif")); });
  EXPECT_TRUE(contains(m, "infinite height at pixel (1, 1)")) << m;
}

TEST(TerrainReader, ImplausibleHeights) {
  ScratchDir dir;
  RasterSpec s;
  s.values = ramp(4, 4, 100, 1, 0);
  s.values[3] = 10500;
  make_raster(dir.file("h.tif"), s);
  auto m = error_of([&] { read_dem(dir.file("h.tif")); });
  EXPECT_TRUE(contains(m, "implausible height 10500")) << m;
  s.values[3] = -12500;
  make_raster(dir.file("l.tif"), s);
  m = error_of([&] { read_dem(dir.file("l.tif")); });
  EXPECT_TRUE(contains(m, "implausible height -12500")) << m;
  // Declaring the value as nodata cures it.
  DemReadOptions o;
  o.nodata = -12500;
  EXPECT_EQ(read_dem(dir.file("l.tif"), o).nodata_count, 1u);
}

TEST(TerrainReader, RotatedGeotransform) {
  ScratchDir dir;
  RasterSpec s;
  s.gt = {500000, 30, 2, 4000000, 2, -30};
  make_raster(dir.file("r.tif"), s);
  const auto m = error_of([&] { read_dem(dir.file("r.tif")); });
  EXPECT_TRUE(contains(m, "rotated")) << m;
}

// Geographic grids at the poles and across the antimeridian: within a degree of a pole a
// clear error (no silent result on a degenerate grid), up to it spacings by cos φ; a
// grid running past 180° E is one continuous grid, its spacing that of its latitudes.
TEST(TerrainReader, GeographicPolesAndAntimeridian) {
  ScratchDir dir;
  RasterSpec s;
  s.epsg = 4326;
  s.width = s.height = 8;
  s.gt = {10.0, 0.1, 0, 89.5, 0, -0.1};  // 89.5° … 88.7° N
  make_raster(dir.file("north.tif"), s);
  auto m = error_of([&] { read_dem(dir.file("north.tif")); });
  EXPECT_TRUE(contains(m, "within 1° of the pole")) << m;
  EXPECT_TRUE(contains(m, "EPSG:3413")) << m;
  s.gt = {10.0, 0.1, 0, -89.2, 0, -0.1};  // south of 89.2° S
  make_raster(dir.file("south.tif"), s);
  m = error_of([&] { read_dem(dir.file("south.tif")); });
  EXPECT_TRUE(contains(m, "pole")) << m;
  s.gt = {10.0, 0.1, 0, 88.9, 0, -0.1};  // 88.9° … 88.1° N: read, with the warning
  make_raster(dir.file("near.tif"), s);
  const auto near = read_dem(dir.file("near.tif"));
  EXPECT_FALSE(near.warnings.empty());
  // dx ∝ cos φ of each row's centre on the WGS 84 parallel (to 0.5 % on the sphere).
  const double ratio = near.field.dx(7) / near.field.dx(0);
  EXPECT_NEAR(ratio, std::cos((88.9 - 0.75) * M_PI / 180) / std::cos((88.9 - 0.05) * M_PI / 180), 5e-3 * ratio);
  s.gt = {179.6, 0.1, 0, 45.4, 0, -0.1};  // 179.6° E … 180.4° E
  make_raster(dir.file("dateline.tif"), s);
  const auto across = read_dem(dir.file("dateline.tif"));
  s.gt = {-0.4, 0.1, 0, 45.4, 0, -0.1};  // the same latitudes at Greenwich
  make_raster(dir.file("greenwich.tif"), s);
  const auto greenwich = read_dem(dir.file("greenwich.tif"));
  for (int j = 0; j < 8; ++j) EXPECT_DOUBLE_EQ(across.field.dx(j), greenwich.field.dx(j)) << j;
  EXPECT_DOUBLE_EQ(across.field.dy, greenwich.field.dy);
}

TEST(TerrainReader, UnknownCrsNeedsScale) {
  ScratchDir dir;
  RasterSpec s;
  s.epsg.reset();
  s.gt = {0, 2, 0, 0, 0, -2};
  make_raster(dir.file("u.tif"), s);
  const auto m = error_of([&] { read_dem(dir.file("u.tif")); });
  EXPECT_TRUE(contains(m, "give its scale")) << m;
  try {
    read_dem(dir.file("u.tif"));
  } catch (const DemError& e) {
    EXPECT_EQ(e.option(), "scale");  // the front end names its flag for it
  }
  DemReadOptions o;
  o.scale = 15.0;
  const auto r = read_dem(dir.file("u.tif"), o);
  EXPECT_DOUBLE_EQ(r.field.dy, 30.0);
  EXPECT_DOUBLE_EQ(r.field.dx(0), 30.0);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_TRUE(contains(r.warnings[0], "no CRS")) << r.warnings[0];
}

TEST(TerrainReader, ScaleOffsetFeetAndZFactor) {
  ScratchDir dir;
  RasterSpec s;
  s.type = GDT_Int16;
  s.values = ramp(4, 4, 10, 1, 4);  // raw 10…25
  s.scale = 0.5;
  s.offset = 100;
  s.unit = "ft";
  make_raster(dir.file("f.tif"), s);
  DemReadOptions o;
  o.z_factor = 2.0;
  const auto r = read_dem(dir.file("f.tif"), o);
  for (int k = 0; k < 16; ++k)
    EXPECT_NEAR(r.field.heights[k], (s.values[k] * 0.5 + 100) * 0.3048 * 2.0, 1e-4);
  EXPECT_EQ(r.vertical_unit, "ft");
  EXPECT_NEAR(r.min_height, (10 * 0.5 + 100) * 0.3048 * 2, 1e-9);
  EXPECT_NEAR(r.max_height, (25 * 0.5 + 100) * 0.3048 * 2, 1e-9);
  o.z_factor = 0;
  EXPECT_THROW(read_dem(dir.file("f.tif"), o), DemError);
}

TEST(TerrainReader, ProjectedFeetCrs) {
  ScratchDir dir;
  RasterSpec s;
  s.epsg = 2227;  // NAD83 / California zone 3 (ftUS)
  s.gt = {6000000, 10, 0, 2000000, 0, -20};
  make_raster(dir.file("p.tif"), s);
  const auto r = read_dem(dir.file("p.tif"));
  const double us_ft = 1200.0 / 3937.0;
  EXPECT_NEAR(r.field.dx(0), 10 * us_ft, 1e-9);
  EXPECT_NEAR(r.field.dy, 20 * us_ft, 1e-9);
  EXPECT_FALSE(r.field.georef.geographic);
}

TEST(TerrainReader, UserScalesWin) {
  ScratchDir dir;
  RasterSpec s;
  make_raster(dir.file("p.tif"), s);
  DemReadOptions o;
  o.xscale = 2.0;  // y keeps the CRS's metres
  const auto r = read_dem(dir.file("p.tif"), o);
  EXPECT_DOUBLE_EQ(r.field.dx(2), 60.0);
  EXPECT_DOUBLE_EQ(r.field.dy, 30.0);
  o.scale = -1;
  EXPECT_THROW(read_dem(dir.file("p.tif"), o), DemError);
}

TEST(TerrainReader, VoidsFilledButInvalid) {
  ScratchDir dir;
  RasterSpec s;
  s.width = s.height = 9;
  s.values = ramp(9, 9, 500, 3, -2);
  s.nodata = -9999;
  s.values[4 * 9 + 4] = -9999;  // one void inside a linear ramp
  s.values[4 * 9 + 5] = -9999;
  make_raster(dir.file("v.tif"), s);
  for (VoidFill fill : {VoidFill::Laplace, VoidFill::Nearest, VoidFill::Minimum}) {
    DemReadOptions o;
    o.fill = fill;
    const auto r = read_dem(dir.file("v.tif"), o);
    EXPECT_EQ(r.nodata_count, 2u);
    EXPECT_FALSE(r.field.is_valid(4, 4));
    EXPECT_FALSE(r.field.is_valid(5, 4));
    ASSERT_TRUE(r.field.nodata.has_value());
    EXPECT_EQ(*r.field.nodata, -9999);
    const double exact = 500 + 3 * 4 - 2 * 4;
    if (fill == VoidFill::Laplace)  // a linear function is harmonic: filled exactly
      EXPECT_NEAR(r.field.at(4, 4), exact, 1e-2);
    else if (fill == VoidFill::Minimum)
      EXPECT_FLOAT_EQ(r.field.at(4, 4), static_cast<float>(r.min_height));
    else
      EXPECT_NEAR(r.field.at(4, 4), exact, 3.0 + 2.0);  // a neighbour's height
  }
}

TEST(TerrainReader, LargeCollarFillIsSmoothAndBounded) {
  ScratchDir dir;
  RasterSpec s;
  s.width = 40;
  s.height = 30;
  s.nodata = -1;
  s.values = ramp(40, 30, 200, 1, 0);
  for (int j = 0; j < 30; ++j)
    for (int i = 0; i < 40; ++i)
      if (std::hypot(i - 20, j - 15) > 10) s.values[j * 40 + i] = -1;
  make_raster(dir.file("c.tif"), s);
  const auto r = read_dem(dir.file("c.tif"));
  for (float z : r.field.heights) {  // maximum principle: within the valid range
    EXPECT_GE(z, r.min_height - 1e-3);
    EXPECT_LE(z, r.max_height + 1e-3);
  }
}

TEST(TerrainReader, SouthUpRasterIsFlipped) {
  ScratchDir dir;
  RasterSpec s;
  s.gt = {500000, 30, 0, 4000000, 0, 30};  // row 0 is the southern edge
  s.values = ramp(4, 4, 100, 0, 1);          // rises northward
  make_raster(dir.file("s.tif"), s);
  const auto r = read_dem(dir.file("s.tif"));
  EXPECT_FLOAT_EQ(r.field.at(0, 0), 103);  // north row first
  EXPECT_FLOAT_EQ(r.field.at(0, 3), 100);
  EXPECT_DOUBLE_EQ(r.field.georef.geotransform[3], 4000120);
  EXPECT_DOUBLE_EQ(r.field.georef.geotransform[5], -30);
}

TEST(TerrainReader, WindowRead) {
  ScratchDir dir;
  RasterSpec s;
  s.width = 10;
  s.height = 8;
  s.values = ramp(10, 8, 0, 1, 100);
  make_raster(dir.file("w.tif"), s);
  DemReadOptions o;
  o.window = PixelRect{3, 2, 4, 5};
  const auto r = read_dem(dir.file("w.tif"), o);
  EXPECT_EQ(r.field.width, 4);
  EXPECT_EQ(r.field.height, 5);
  EXPECT_EQ(r.source_width, 10);
  EXPECT_FLOAT_EQ(r.field.at(0, 0), 3 + 200);
  EXPECT_DOUBLE_EQ(r.field.georef.geotransform[0], 500000 + 3 * 30);
  EXPECT_DOUBLE_EQ(r.field.georef.geotransform[3], 4000000 - 2 * 30);
  o.window = PixelRect{8, 0, 4, 4};
  EXPECT_THROW(read_dem(dir.file("w.tif"), o), DemError);
}

TEST(TerrainReader, MosaicOfTilesAndDirectory) {
  ScratchDir dir;
  testing::fs::create_directory(dir.path() / "tiles");
  RasterSpec west, east;
  west.values = ramp(4, 4, 100, 1, 0);
  east.values = ramp(4, 4, 104, 1, 0);
  east.gt[0] += 4 * 30;
  const auto a = make_raster((dir.path() / "tiles" / "a.tif").string(), west);
  const auto b = make_raster((dir.path() / "tiles" / "b.tif").string(), east);
  std::ofstream((dir.path() / "tiles" / "readme.txt").string()) << "not a raster";
  for (const auto& r : {read_dem(std::vector<std::string>{a, b}), read_dem((dir.path() / "tiles").string())}) {
    ASSERT_EQ(r.field.width, 8);
    ASSERT_EQ(r.field.height, 4);
    for (int i = 0; i < 8; ++i) EXPECT_FLOAT_EQ(r.field.at(i, 2), 100 + i);
    EXPECT_DOUBLE_EQ(r.field.dx(0), 30);
  }
  RasterSpec other = east;
  other.epsg = 32612;
  const auto c = make_raster(dir.file("c.tif"), other);
  const auto m = error_of([&] { read_dem(std::vector<std::string>{a, c}); });
  EXPECT_TRUE(contains(m, "different CRSs")) << m;
  testing::fs::create_directory(dir.path() / "empty");
  EXPECT_THROW(read_dem((dir.path() / "empty").string()), DemError);
}

TEST(TerrainReader, MosaicGapsAreNodata) {
  ScratchDir dir;
  RasterSpec nw, se;  // no nodata value declared: the gaps must still be voids
  nw.values = ramp(4, 4, 100, 1, 0);
  se.values = ramp(4, 4, 200, 1, 0);
  se.gt[0] += 4 * 30;
  se.gt[3] -= 4 * 30;
  const auto a = make_raster(dir.file("nw.tif"), nw);
  const auto b = make_raster(dir.file("se.tif"), se);
  const auto r = read_dem(std::vector<std::string>{a, b});
  ASSERT_EQ(r.field.width, 8);
  ASSERT_EQ(r.field.height, 8);
  EXPECT_EQ(r.nodata_count, 32u);
  EXPECT_FALSE(r.field.is_valid(6, 1));  // north-east gap
  EXPECT_FALSE(r.field.is_valid(1, 6));  // south-west gap
  EXPECT_TRUE(r.field.is_valid(6, 6));
  EXPECT_FLOAT_EQ(r.field.at(6, 6), 202);
  EXPECT_TRUE(r.field.nodata.has_value());
  DemReadOptions band2;
  band2.band = 2;  // the mosaic's alpha band is not a DEM band
  EXPECT_THROW(read_dem(std::vector<std::string>{a, b}, band2), DemError);
  const auto info = inspect_dem(std::vector<std::string>{a, b});
  EXPECT_EQ(info.bands, 1);
  EXPECT_EQ(info.width, 8);
  EXPECT_EQ(info.files.size(), 2u);
}

TEST(TerrainReader, InspectDoesNotReadPixels) {
  ScratchDir dir;
  RasterSpec s;
  s.width = 7;
  s.height = 5;
  s.nodata = -1;
  make_raster(dir.file("i.tif"), s);
  const auto info = inspect_dem(dir.file("i.tif"));
  EXPECT_EQ(info.width, 7);
  EXPECT_EQ(info.height, 5);
  EXPECT_EQ(info.bands, 1);
  EXPECT_EQ(info.nodata, -1);
  EXPECT_FALSE(info.georef.crs_wkt.empty());
}

// ---- Real DEMs (shared/dem) ----

class RealDem : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!testing::fs::exists(shared_dem("README.md"))) GTEST_SKIP() << "shared DEM directory missing";
  }
};

// Length of one degree of latitude on WGS84 (standard series, independent of
// GeographicLib), and of longitude on a sphere of 111 320 m per degree.
double meridian_m_per_degree(double lat_deg) {
  const double p = lat_deg * M_PI / 180;
  return 111132.954 - 559.822 * std::cos(2 * p) + 1.175 * std::cos(4 * p);
}

void check_geographic_spacing(const DemReadResult& r) {
  const auto& gt = r.field.georef.geotransform;
  ASSERT_TRUE(r.field.georef.geographic);
  for (int j = 0; j < r.field.height; j += std::max(1, r.field.height / 7)) {
    const double lat = gt[3] + (j + 0.5) * gt[5];
    const double expect_dx = 111320.0 * std::cos(lat * M_PI / 180) * gt[1];
    EXPECT_NEAR(r.field.dx(j), expect_dx, 0.005 * expect_dx) << "row " << j;
  }
  const double mid_lat = gt[3] + 0.5 * r.field.height * gt[5];
  const double expect_dy = meridian_m_per_degree(mid_lat) * std::abs(gt[5]);
  EXPECT_NEAR(r.field.dy, expect_dy, 0.0005 * expect_dy);
}

TEST_F(RealDem, PyreneesGeographicPixelIsPoint) {
  const auto r = read_dem(shared_dem("pyrenees_andorra_srtm3_4326.tif"));
  EXPECT_EQ(r.field.width, 1201);
  EXPECT_EQ(r.field.height, 1201);
  EXPECT_EQ(r.nodata_count, 7652u);
  EXPECT_NEAR(r.field.georef.geotransform[0], 0.999583, 1e-6);  // corner-based (PixelIsPoint kept)
  EXPECT_NEAR(r.field.georef.geotransform[3], 43.000417, 1e-6);
  EXPECT_NEAR(r.min_height, 349, 0.5);
  EXPECT_NEAR(r.max_height, 3100, 0.5);
  check_geographic_spacing(r);
  EXPECT_NEAR(r.field.dy, 92.6, 0.5);  // README: ≈ 93 m N–S × 68 m E–W
  EXPECT_NEAR(r.field.dx(600), 68.0, 1.0);
  ASSERT_TRUE(r.field.nodata.has_value());
  EXPECT_EQ(*r.field.nodata, -32768);
  // Voids are filled within the surrounding relief, never with the nodata value.
  for (std::size_t k = 0; k < r.field.size(); ++k)
    if (!r.field.valid[k]) {
      ASSERT_GE(r.field.heights[k], r.min_height - 1);
      ASSERT_LE(r.field.heights[k], r.max_height + 1);
    }
}

TEST_F(RealDem, GeographicNodataCounts) {
  struct Case {
    const char* file;
    std::size_t voids;
    double lo, hi;
  };
  for (const Case& c : {Case{"nice_monaco_coast_srtm3_4326.tif", 1595, -11, 2064},
                        Case{"franconia_hills_srtm3_4326.tif", 20, 234, 920},
                        Case{"luxembourg_elev_4326.tif", 3942, 141, 547},
                        Case{"cascades_skykomish_srtm1_4326.tif", 0, 124, 1901}}) {
    SCOPED_TRACE(c.file);
    const auto r = read_dem(shared_dem(c.file));
    EXPECT_EQ(r.nodata_count, c.voids);
    EXPECT_NEAR(r.min_height, c.lo, 0.5);
    EXPECT_NEAR(r.max_height, c.hi, 0.5);
    check_geographic_spacing(r);
  }
}

TEST_F(RealDem, CascadesOneArcSecond) {
  const auto r = read_dem(shared_dem("cascades_skykomish_srtm1_4326.tif"));
  EXPECT_EQ(r.field.width, 720);
  EXPECT_EQ(r.field.height, 360);
  EXPECT_NEAR(r.field.dx(180), 20.7, 0.5);  // README: ≈ 21 m E–W × 31 m N–S at 47.85°N
  EXPECT_NEAR(r.field.dy, 30.9, 0.3);
}

TEST_F(RealDem, ProjectedDems) {
  struct Case {
    const char* file;
    int w, h;
    double spacing, lo, hi;
    std::size_t voids;
  };
  for (const Case& c : {Case{"big_tujunga_srtm30_utm11n.tif", 1197, 643, 30, 315, 2295, 0},
                        Case{"mt_st_helens_usgs30_utm10n.tif", 327, 468, 30, 682, 2543, 4151},
                        Case{"similkameen_bc_50m_bcalbers.tif", 430, 516, 50, 350, 2583, 0},
                        Case{"olinda_dem_utm25s.tif", 111, 111, 89.994, -1, 88, 0},
                        Case{"slovenia_lidar1m_d96tm.tif", 1000, 1000, 1, 254.97, 325.05, 0}}) {
    SCOPED_TRACE(c.file);
    const auto r = read_dem(shared_dem(c.file));
    EXPECT_EQ(r.field.width, c.w);
    EXPECT_EQ(r.field.height, c.h);
    EXPECT_NEAR(r.field.dx(0), c.spacing, 1e-3 * c.spacing);
    EXPECT_NEAR(r.field.dx(c.h - 1), c.spacing, 1e-3 * c.spacing);
    EXPECT_NEAR(r.field.dy, c.spacing, 1e-3 * c.spacing);
    EXPECT_EQ(r.nodata_count, c.voids);
    EXPECT_NEAR(r.min_height, c.lo, 0.5);
    EXPECT_NEAR(r.max_height, c.hi, 0.5);
    EXPECT_FALSE(r.field.georef.geographic);
    EXPECT_FALSE(r.field.georef.crs_wkt.empty());
  }
}

TEST_F(RealDem, OlindaSeaIsData) {
  const auto r = read_dem(shared_dem("olinda_dem_utm25s.tif"));
  const auto zeros = std::count(r.field.heights.begin(), r.field.heights.end(), 0.0f);
  EXPECT_NEAR(static_cast<double>(zeros) / r.field.size(), 0.167, 0.005);  // README: 16.7 % are 0
}

// Other GDAL formats: the same heights through an SRTM .hgt copy, and an ASCII grid
// (no CRS: needs a scale).
TEST_F(RealDem, SrtmHgtAndAsciiGrid) {
  ScratchDir dir;
  testing::ensure_gdal();
  const auto tif = read_dem(shared_dem("pyrenees_andorra_srtm3_4326.tif"));
  {
    GDALDataset* src = GDALDataset::Open(shared_dem("pyrenees_andorra_srtm3_4326.tif").c_str(), GDAL_OF_RASTER);
    ASSERT_TRUE(src);
    GDALDataset* hgt = GetGDALDriverManager()->GetDriverByName("SRTMHGT")->CreateCopy(
        dir.file("N42E001.hgt").c_str(), src, FALSE, nullptr, nullptr, nullptr);
    GDALDataset* asc = GetGDALDriverManager()->GetDriverByName("AAIGrid")->CreateCopy(
        dir.file("grid.asc").c_str(), src, FALSE, nullptr, nullptr, nullptr);
    ASSERT_TRUE(hgt && asc);
    GDALClose(GDALDataset::ToHandle(hgt));
    GDALClose(GDALDataset::ToHandle(asc));
    GDALClose(GDALDataset::ToHandle(src));
    testing::fs::remove(dir.file("grid.prj"));  // an ASCII grid often comes without one
  }
  const auto hgt = read_dem(dir.file("N42E001.hgt"));
  EXPECT_EQ(hgt.nodata_count, tif.nodata_count);
  EXPECT_EQ(hgt.field.heights, tif.field.heights);
  EXPECT_DOUBLE_EQ(hgt.field.dy, tif.field.dy);
  EXPECT_THROW(read_dem(dir.file("grid.asc")), DemError);
  DemReadOptions o;
  o.scale = 111120;
  const auto asc = read_dem(dir.file("grid.asc"), o);
  EXPECT_EQ(asc.nodata_count, tif.nodata_count);
  EXPECT_NEAR(asc.field.dy, 111120 / 1200.0, 1e-6);
}

TEST_F(RealDem, GdaldemScaleOverridesEllipsoid) {
  DemReadOptions o;
  o.scale = 111120;  // gdaldem -s 111120: no cos(latitude), as the user asked
  const auto r = read_dem(shared_dem("luxembourg_elev_4326.tif"), o);
  EXPECT_NEAR(r.field.dx(0), 111120 * r.field.georef.geotransform[1], 1e-6);
  EXPECT_NEAR(r.field.dy, 111120 * std::abs(r.field.georef.geotransform[5]), 1e-6);
}

}  // namespace
}  // namespace skylit::terrain
