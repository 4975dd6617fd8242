// Per-zoom height windows (terrain/tile_window.h): against the gdalwarp program run on
// the DEM file itself, seamless halos between neighbouring windows, ground spacing
// against PROJ's latitudes, and the outside/no-CRS policies.
#include <gtest/gtest.h>
#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "terrain/dem_reader.h"
#include "terrain/tile_window.h"
#include "terrain_test_util.h"

namespace skylit::terrain {
namespace {

namespace fs = std::filesystem;
using testing::ScratchDir;

constexpr double kHalfWorld = 20037508.342789244;  // WebMercatorQuad, independent of our constant

std::string dem_path(const char* name) { return std::string(SKYLIT_SHARED_DIR) + "/dem/" + name; }

#define REQUIRE_FILE(path) SKYLIT_REQUIRE(testing::missing_file(path))
#define REQUIRE_GDALWARP() \
  SKYLIT_REQUIRE(std::system("gdalwarp --version > /dev/null 2>&1") == 0 ? "" : "gdalwarp is not on PATH")

std::string exact(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

struct Raster {
  int width = 0, height = 0;
  std::array<double, 6> gt{};
  std::vector<float> values;
};

// gdalwarp over tiles [x0..x1] × [y0..y1] of zoom z with a halo, the extent derived
// here from the published half width; `args` are the resampling/warper options.
// `x_origin` is the west edge of the target CRS' world (−kHalfWorld for EPSG:3857).
Raster gdalwarp_window(const std::string& dem, int z, int x0, int y0, int x1, int y1, int halo,
                       const std::vector<std::string>& args, const ScratchDir& dir, double x_origin = -kHalfWorld) {
  const double pix = 2 * kHalfWorld / (256.0 * std::pow(2.0, z));
  const double xmin = x_origin + (x0 * 256.0 - halo) * pix, xmax = x_origin + ((x1 + 1) * 256.0 + halo) * pix;
  const double ymax = kHalfWorld - (y0 * 256.0 - halo) * pix, ymin = kHalfWorld - ((y1 + 1) * 256.0 + halo) * pix;
  const int w = (x1 - x0 + 1) * 256 + 2 * halo, h = (y1 - y0 + 1) * 256 + 2 * halo;
  const std::string out = dir.file("gdalwarp_" + std::to_string(z) + "_" + std::to_string(x0) + ".tif");
  std::string cmd = "gdalwarp -q -overwrite -te " + exact(xmin) + " " + exact(ymin) + " " + exact(xmax) + " " +
                    exact(ymax) + " -ts " + std::to_string(w) + " " + std::to_string(h);
  for (const auto& a : args) cmd += " '" + a + "'";
  cmd += " '" + dem + "' '" + out + "'";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  GDALAllRegister();
  Raster r;
  const auto close = [](GDALDataset* d) { GDALClose(GDALDataset::ToHandle(d)); };
  std::unique_ptr<GDALDataset, decltype(close)> ds(GDALDataset::Open(out.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY),
                                                   close);
  if (!ds) {
    ADD_FAILURE() << "cannot open " << out;
    return r;
  }
  r.width = ds->GetRasterXSize();
  r.height = ds->GetRasterYSize();
  ds->GetGeoTransform(r.gt.data());
  r.values.resize(static_cast<std::size_t>(r.width) * r.height);
  EXPECT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, r.width, r.height, r.values.data(), r.width, r.height,
                                           GDT_Float32, 0, 0, nullptr),
            CE_None);
  return r;
}

// The largest height step between neighbouring valid DEM samples (metres).
double max_step(const HeightField& dem) {
  double l = 0;
  for (int y = 0; y < dem.height; ++y)
    for (int x = 0; x < dem.width; ++x) {
      if (!dem.is_valid(x, y)) continue;
      if (x + 1 < dem.width && dem.is_valid(x + 1, y)) l = std::max(l, double(std::abs(dem.at(x + 1, y) - dem.at(x, y))));
      if (y + 1 < dem.height && dem.is_valid(x, y + 1)) l = std::max(l, double(std::abs(dem.at(x, y + 1) - dem.at(x, y))));
    }
  return l;
}

// How far a height may move when every source point the warper asks for moves by up
// to eps source pixels per axis (the window's transform against gdalwarp's exact one),
// with L the DEM's largest step between neighbouring samples:
//  * cubic at scale 1 (Keys, a = −0.5): on [0, 1] between samples the derivative is
//    (0.5 − 2t + 1.5t²)·d₋ + (0.5 + 3t − 3t²)·d₀ + (−t + 1.5t²)·d₊ in the three steps
//    d around it, at most 1.5 L (t = ½); across rows the weights' absolute sum is at
//    most 1.25 (t = ½: 1/16 + 9/16 + 9/16 + 1/16), so |∂h/∂s| ≤ 1.875 L per axis.
//  * average over a footprint of W × H source pixels (W = 1/xscale): moving one of its
//    four edges by eps changes the mean by at most eps/W (or eps/H) times the range of
//    heights in it, ≤ (W + H + 2)·L.
// eps is the node rule's bound with 10 % slack (terrain_zoom_transform_test measures
// the error under it).
double shift_tolerance(const WarpSettings& ws, double l) {
  const double eps = 1.1 * ws.node_error_bound_px;
  if (ws.resampling == Resampling::Average) {
    const double w = 1 / ws.xscale, h = 1 / ws.yscale;
    return 2 * eps * (1 / w + 1 / h) * (w + h + 2) * l;
  }
  EXPECT_EQ(ws.resampling, Resampling::Cubic);
  EXPECT_EQ(ws.xscale, 1.0);
  EXPECT_EQ(ws.yscale, 1.0);
  return 2 * eps * 1.875 * l;
}

// The window against gdalwarp -et 0: same valid pixels, heights within the shift the
// approximate transform allows plus float rounding (4e-7 relative: a few ulps).
void expect_matches(const TileWindow& win, const Raster& ref, double shift) {
  ASSERT_EQ(win.field.width, ref.width);
  ASSERT_EQ(win.field.height, ref.height);
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(win.field.georef.geotransform[k], ref.gt[k], 1e-6) << "gt " << k;
  std::size_t mask_diff = 0, valid = 0, over = 0;
  double worst = 0;
  for (std::size_t k = 0; k < ref.values.size(); ++k) {
    const bool ref_valid = !std::isnan(ref.values[k]);
    if (ref_valid != (win.field.valid[k] != 0)) ++mask_diff;
    if (ref_valid && win.field.valid[k]) {
      ++valid;
      const double d = std::abs(double(ref.values[k]) - win.field.heights[k]);
      worst = std::max(worst, d);
      over += d > shift + 4e-7 * std::max(1.0, std::abs(double(ref.values[k])));
    }
  }
  std::printf("largest difference from gdalwarp -et 0: %.3g m (allowed %.3g m + rounding)\n", worst, shift);
  EXPECT_EQ(mask_diff, 0u);
  EXPECT_GT(valid, 0u);
  EXPECT_EQ(over, 0u) << "of " << valid << " pixels differ from gdalwarp by more than " << shift
                      << " m + rounding; largest " << worst << " m";
}

TEST(TileWindow, MatchesGdalwarpCubicAtNativeZoom) {
  const std::string path = dem_path("big_tujunga_srtm30_utm11n.tif");
  REQUIRE_FILE(path);
  REQUIRE_GDALWARP();
  const HeightField dem = read_dem(path).field;
  const TileWindowSource source(dem);
  ASSERT_EQ(source.native_zoom(), 13);
  // Two tiles around the DEM's centre (13/1407/3263, see terrain_tile_grid_test), halo 16.
  const TileRange tiles{13, 1407, 3263, 1408, 3263};
  const TileWindowOptions opt{.tile_size = 256, .halo = 16};
  const TileWindow win = source.window(tiles, opt);
  EXPECT_EQ(win.resampling, Resampling::Cubic);  // z ≥ native
  const WarpSettings ws = source.warp_settings(13, opt);
  EXPECT_EQ(ws.xscale, 1.0);  // upsampling: 15.8 m pixels from 30 m ones
  ScratchDir dir;
  expect_matches(win, gdalwarp_window(path, 13, 1407, 3263, 1408, 3263, 16, ws.arguments(), dir),
                 shift_tolerance(ws, max_step(dem)));
  // The arguments are the documented ones.
  const std::vector<std::string> expect_head{"-t_srs", "EPSG:3857", "-r", "cubic", "-et", "0", "-ot", "Float32",
                                             "-dstnodata", "nan"};
  const std::vector<std::string> args = ws.arguments();
  EXPECT_EQ(std::vector<std::string>(args.begin(), args.begin() + 10), expect_head);
}

TEST(TileWindow, MatchesGdalwarpAverageBelowNativeZoom) {
  const std::string path = dem_path("big_tujunga_srtm30_utm11n.tif");
  REQUIRE_FILE(path);
  REQUIRE_GDALWARP();
  const HeightField dem = read_dem(path).field;
  const TileWindowSource source(dem);
  // z 10: every tile touching the DEM (x 175…176, y 407…408 from its lon/lat corners).
  const TileRange tiles = tiles_covering(LonLatBox{-118.3457, 34.2314, -117.9531, 34.4090}, 10);
  ASSERT_FALSE(tiles.empty());
  const TileWindowOptions opt{.halo = 8};
  const TileWindow win = source.window(tiles, opt);
  EXPECT_EQ(win.resampling, Resampling::Average);
  const WarpSettings ws = source.warp_settings(10, opt);
  // Ground pixel at z 10, 34.3203°N: 156543.034 / 1024 · cos φ = 126.26 m; 30 / 126.26 = 0.2376.
  EXPECT_NEAR(ws.xscale, 0.2376, 2e-4);
  EXPECT_NEAR(ws.yscale, 0.2376, 2e-4);
  ScratchDir dir;
  expect_matches(win, gdalwarp_window(path, 10, tiles.x0, tiles.y0, tiles.x1, tiles.y1, 8, ws.arguments(), dir),
                 shift_tolerance(ws, max_step(dem)));
  EXPECT_FALSE(win.empty());
  EXPECT_LT(win.valid_count, win.field.size());  // the DEM does not fill its tiles
}

TEST(TileWindow, MatchesGdalwarpOnAGeographicDemWithVoids) {
  // Luxembourg: EPSG:4326, 30″ pixels, 46 % nodata outside the border.
  const std::string path = dem_path("luxembourg_elev_4326.tif");
  REQUIRE_FILE(path);
  REQUIRE_GDALWARP();
  const DemReadResult dem = read_dem(path);
  const TileWindowSource source(dem.field);
  // Ground resolution min(927 m, 598 m) = 598 m at 49.8°N; z 8: 156543/256 · cos φ = 395 m → native 8.
  ASSERT_EQ(source.native_zoom(), 8);
  const TileRange tiles = tiles_covering(LonLatBox{5.74, 49.45, 6.53, 50.19}, 8);
  const TileWindowOptions opt{.halo = 4};
  const TileWindow win = source.window(tiles, opt);
  ScratchDir dir;
  const WarpSettings ws = source.warp_settings(8, opt);
  expect_matches(win, gdalwarp_window(path, 8, tiles.x0, tiles.y0, tiles.x1, tiles.y1, 4, ws.arguments(), dir),
                 shift_tolerance(ws, max_step(dem.field)));
  // Voids are filled (finite) but marked.
  for (std::size_t k = 0; k < win.field.size(); ++k) ASSERT_TRUE(std::isfinite(win.field.heights[k]));
  EXPECT_EQ(win.field.nodata, dem.field.nodata);
}

// A DEM across the antimeridian, stored in degrees 179.85…180.15° E: its columns run
// from the world's last (2^z − 1) into the next world's first (2^z, wrapping to 0), and
// one window over both equals gdalwarp's into a spherical Mercator centred on 180°,
// where both sides are one plane (the same grid shifted by half a world).
TEST(TileWindow, AWindowAcrossTheAntimeridianMatchesGdalwarpCentredOn180) {
  REQUIRE_GDALWARP();
  ScratchDir dir;
  testing::RasterSpec spec;
  spec.width = 120;
  spec.height = 100;
  spec.epsg = 4326;
  spec.gt = {179.85, 0.0025, 0, -17.8, 0, -0.0025};  // ≈ 265 m pixels at 18° S
  for (int j = 0; j < spec.height; ++j)
    for (int i = 0; i < spec.width; ++i)
      spec.values.push_back(800.0 + 300.0 * std::sin(i * 0.11) * std::cos(j * 0.07) + 2.0 * i);
  const std::string path = testing::make_raster(dir.file("dateline.tif"), spec);
  const HeightField dem = read_dem(path).field;
  const TileWindowSource source(dem);
  const int z = 10;  // 146 m ground pixels: cubic at scale 1
  const TileRange tiles = tiles_covering(dem_mercator_bounds(dem), z);
  ASSERT_EQ(tiles.x0, 1023);
  ASSERT_EQ(tiles.x1, 1024);
  const TileWindowOptions opt{.halo = 8};
  const TileWindow win = source.window(tiles, opt);
  const WarpSettings ws = source.warp_settings(z, opt);
  ASSERT_EQ(ws.resampling, Resampling::Cubic);
  std::vector<std::string> args = ws.arguments();
  ASSERT_EQ(args[0], "-t_srs");
  args[1] = "+proj=merc +a=6378137 +b=6378137 +lon_0=180 +x_0=0 +y_0=0 +k=1 +units=m +nadgrids=@null +wktext +no_defs";
  Raster ref = gdalwarp_window(path, z, tiles.x0, tiles.y0, tiles.x1, tiles.y1, opt.halo, args, dir, -2 * kHalfWorld);
  ref.gt[0] += kHalfWorld;  // back to EPSG:3857, continued past its east edge
  expect_matches(win, ref, shift_tolerance(ws, max_step(dem)));
  // Both sides of 180° hold the DEM.
  const int half = opt.halo + 256;
  long west = 0, east = 0;
  for (int j = 0; j < win.field.height; ++j)
    for (int i = 0; i < win.field.width; ++i) (i < half ? west : east) += win.field.is_valid(i, j);
  EXPECT_GT(west, 1000);
  EXPECT_GT(east, 1000);
}

// A DEM staged on disk (as `skylit tiles` stages one over its memory limit) gives the
// windows of the in-memory copy, bit for bit: geographic, with voids, at two zooms.
TEST(TileWindow, AWindowFromTheDiskCopyEqualsTheInMemoryOne) {
  const std::string path = dem_path("luxembourg_elev_4326.tif");
  REQUIRE_FILE(path);
  ScratchDir temp;
  StagingOptions disk;
  disk.memory_limit_bytes = 0;
  disk.directory = temp.path();
  disk.strip_pixels = 4096;
  std::vector<std::string> warnings;
  const TileWindowSource on_disk(StagedDem::read({path}, {}, disk, warnings));
  const TileWindowSource in_memory(read_dem(path).field);
  ASSERT_TRUE(on_disk.dem().on_disk());
  for (int z : {8, 10}) {
    const TileRange tiles = tiles_covering(LonLatBox{5.9, 49.6, 6.2, 49.9}, z);
    const TileWindowOptions opt{.halo = 6};
    const TileWindow a = on_disk.window(tiles, opt), b = in_memory.window(tiles, opt);
    ASSERT_GT(a.valid_count, 0u);
    ASSERT_LT(a.valid_count, a.field.size()) << "the window should reach a void";
    EXPECT_EQ(a.valid_count, b.valid_count) << "z " << z;
    EXPECT_TRUE(a.field.heights == b.field.heights) << "z " << z;
    EXPECT_TRUE(a.field.valid == b.field.valid) << "z " << z;
    EXPECT_EQ(a.field.nodata, b.field.nodata);
  }
  EXPECT_TRUE(temp.listing().empty());
}

// Every global pixel held by both windows: same validity, the same height bit for bit
// (the transform is a function of global pixel coordinates alone, zoom_transform.h).
void expect_seamless(const TileWindow& a, const TileWindow& b, bool shares_data = true) {
  ASSERT_EQ(a.tiles.z, b.tiles.z);
  const long long T = a.tile_size;
  const long long ax0 = a.tiles.x0 * T - a.halo, ay0 = a.tiles.y0 * T - a.halo;
  const long long bx0 = b.tiles.x0 * T - b.halo, by0 = b.tiles.y0 * T - b.halo;
  std::size_t shared = 0, valid = 0, differ = 0;
  for (int j = 0; j < a.field.height; ++j)
    for (int i = 0; i < a.field.width; ++i) {
      const long long bi = ax0 + i - bx0, bj = ay0 + j - by0;
      if (bi < 0 || bj < 0 || bi >= b.field.width || bj >= b.field.height) continue;
      ++shared;
      const bool va = a.field.is_valid(i, j), vb = b.field.is_valid(int(bi), int(bj));
      const float ha = a.field.at(i, j), hb = b.field.at(int(bi), int(bj));
      if (va != vb || (va && ha != hb)) {
        if (differ == 0)
          ADD_FAILURE() << "first difference at window pixel (" << i << ", " << j << "): valid " << va << " vs "
                        << vb << ", " << a.field.at(i, j) << " vs " << b.field.at(int(bi), int(bj));
        ++differ;
      }
      valid += va;
    }
  EXPECT_GT(shared, 0u);
  if (shares_data) {
    EXPECT_GT(valid, 0u);
  }
  EXPECT_EQ(differ, 0u) << "of " << shared << " shared pixels";
}

TEST(TileWindow, HalosEqualTheNeighboursPixels) {
  const std::string path = dem_path("big_tujunga_srtm30_utm11n.tif");
  REQUIRE_FILE(path);
  const TileWindowSource source(read_dem(path).field);
  struct Case {
    int z, x, y;
    std::optional<Resampling> r;
  };
  // Native zoom (cubic), below it (average), and cubic below it: downsampling, where
  // GDAL's per-chunk kernel scale would differ between windows.
  for (const Case c : {Case{13, 1407, 3263, std::nullopt}, Case{11, 351, 815, std::nullopt},
                       Case{11, 351, 815, Resampling::Cubic}, Case{11, 351, 815, Resampling::Lanczos}}) {
    SCOPED_TRACE("z " + std::to_string(c.z) + " " + (c.r ? std::string(resampling_name(*c.r)) : "default"));
    const TileWindowOptions opt{.halo = 24, .resampling = c.r};
    const TileWindow centre = source.window({c.z, c.x, c.y, c.x, c.y}, opt);
    // The DEM spans tiles x−1…x+1 at both zooms; at z 11 it lies in row y alone.
    expect_seamless(centre, source.window({c.z, c.x + 1, c.y, c.x + 1, c.y}, opt));  // east
    expect_seamless(centre, source.window({c.z, c.x - 1, c.y, c.x - 1, c.y}, opt));  // west
    expect_seamless(centre, source.window({c.z, c.x, c.y + 1, c.x, c.y + 1}, opt), c.z == 13);  // south
    expect_seamless(centre, source.window({c.z, c.x - 1, c.y - 1, c.x - 1, c.y - 1}, opt), false);  // north-west
    // A 2×2-tile window without halo holds the centre tile and its halo's east/south part.
    expect_seamless(centre, source.window({c.z, c.x, c.y, c.x + 1, c.y + 1}, {.halo = 0, .resampling = c.r}));
  }
}

TEST(TileWindow, GroundSpacingFollowsCosLatitude) {
  const std::string path = dem_path("big_tujunga_srtm30_utm11n.tif");
  REQUIRE_FILE(path);
  const TileWindowSource source(read_dem(path).field);
  const TileWindow win = source.window({10, 175, 407, 176, 408}, {.halo = 64});
  const HeightField& f = win.field;
  ASSERT_EQ(f.height, 2 * 256 + 128);
  OGRSpatialReference merc, geo;
  merc.importFromEPSG(3857);
  geo.importFromEPSG(4326);
  merc.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  geo.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  const std::unique_ptr<OGRCoordinateTransformation> inv(OGRCreateCoordinateTransformation(&merc, &geo));
  const double pix = 2 * kHalfWorld / (256.0 * 1024);
  double sum = 0;
  for (int j = 0; j < f.height; ++j) {
    double x = f.georef.geotransform[0], y = f.georef.geotransform[3] - (j + 0.5) * pix;
    ASSERT_TRUE(inv->Transform(1, &x, &y));
    const double expect = pix * std::cos(y * M_PI / 180);  // PROJ's latitude of the row centre
    EXPECT_NEAR(f.dx(j), expect, 1e-9 * expect) << "row " << j;
    EXPECT_EQ(win.dy_per_row[j], f.dx(j));
    sum += win.dy_per_row[j];
  }
  EXPECT_GT(f.dx(0), 0);
  EXPECT_LT(f.dx(0), f.dx(f.height - 1));  // pixels shrink northward on the ground
  EXPECT_NEAR(f.dy, sum / f.height, 1e-6 * f.dy);
  // max_dy_error ≈ sin φ · (rows / 2) · (2π / (256 · 2^z)) at the window's edge rows.
  const double phi = 34.32 * M_PI / 180;
  EXPECT_NEAR(win.max_dy_error(), std::sin(phi) * f.height * M_PI / (256.0 * 1024), 0.05 * win.max_dy_error());
  // Slopes see ground metres: shading must not use metric_spacing's 3857 metres.
  EXPECT_LT(f.mean_dx(), 0.9 * pix);
}

TEST(TileWindow, OutsideTheDemIsMarkedNotAnError) {
  const std::string path = dem_path("big_tujunga_srtm30_utm11n.tif");
  REQUIRE_FILE(path);
  const TileWindowSource source(read_dem(path).field);
  // Far away (the Atlantic at z 13): empty, all invalid, heights 0.
  const TileWindow far = source.window({13, 3000, 3000, 3000, 3000}, {.halo = 2});
  EXPECT_TRUE(far.empty());
  EXPECT_EQ(far.field.width, 260);
  for (std::size_t k = 0; k < far.field.size(); ++k) {
    ASSERT_EQ(far.field.valid[k], 0);
    ASSERT_EQ(far.field.heights[k], 0.0f);
  }
  // A halo past the world's corner (west of −180°, north of 85.05°) is just more outside.
  const TileWindow corner = source.window({3, 0, 0, 0, 0}, {.halo = 8});
  EXPECT_TRUE(corner.empty());
  EXPECT_EQ(corner.field.height, 272);
  // The DEM's west edge (118.3457°W at the top, 118.3430°W at the bottom) crosses global
  // pixel column (180 − 118.345)/360 · 8192 · 256 ≈ 1403 · 256 ± 12 at z 13: with a 64-px
  // halo the window over tile 1403 is invalid on the west, valid on the east, every
  // height finite (filled).
  const TileWindow edge = source.window({13, 1403, 3263, 1403, 3263}, {.halo = 64});
  EXPECT_FALSE(edge.empty());
  EXPECT_LT(edge.valid_count, edge.field.size());
  EXPECT_FALSE(edge.field.is_valid(0, 192));
  EXPECT_FALSE(edge.field.is_valid(40, 192));
  EXPECT_TRUE(edge.field.is_valid(64 + 40, 192));
  for (std::size_t k = 0; k < edge.field.size(); ++k) ASSERT_TRUE(std::isfinite(edge.field.heights[k]));
  EXPECT_TRUE(edge.field.nodata.has_value());
}

TEST(TileWindow, ErrorsAreOneLine) {
  HeightField f(16, 16, 30.0);
  try {
    TileWindowSource s(f);  // no CRS
    FAIL() << "no exception";
  } catch (const DemError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("no CRS"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos);
  }
  f.georef = skylit::terrain::testing::epsg_georef(32611, {394000, 30, 0, 3798000, 0, -30});
  const TileWindowSource s(f);
  EXPECT_THROW(s.window({13, 1407, 3263, 1406, 3263}), std::invalid_argument);  // empty range
  EXPECT_THROW(s.window({2, 0, 0, 4, 0}), std::invalid_argument);               // beyond zoom 2
  EXPECT_THROW(s.window({13, 1407, 3263, 1407, 3263}, {.halo = -1}), std::invalid_argument);
  EXPECT_THROW(s.window({13, 1407, 3263, 1407, 3263}, {.tile_size = 300}), std::invalid_argument);
  EXPECT_THROW(s.window({31, 0, 0, 0, 0}), std::invalid_argument);
}

TEST(TileWindow, TileRectsAndResamplingNames) {
  TileWindow w;
  w.tiles = {5, 10, 20, 11, 21};
  w.tile_size = 256;
  w.halo = 8;
  EXPECT_EQ(w.tile_rect({5, 10, 20}), (PixelRect{8, 8, 256, 256}));
  EXPECT_EQ(w.tile_rect({5, 11, 21}), (PixelRect{264, 264, 256, 256}));
  EXPECT_THROW(w.tile_rect({5, 12, 20}), std::out_of_range);
  EXPECT_THROW(w.tile_rect({6, 10, 20}), std::out_of_range);
  for (auto r : {Resampling::Nearest, Resampling::Bilinear, Resampling::Cubic, Resampling::CubicSpline,
                 Resampling::Lanczos, Resampling::Average})
    EXPECT_EQ(parse_resampling(resampling_name(r)), r);
  EXPECT_EQ(resampling_name(Resampling::Nearest), "near");
  EXPECT_FALSE(parse_resampling("bicubic").has_value());
  EXPECT_EQ(default_resampling(13, 13), Resampling::Cubic);
  EXPECT_EQ(default_resampling(14, 13), Resampling::Cubic);
  EXPECT_EQ(default_resampling(12, 13), Resampling::Average);
}

}  // namespace
}  // namespace skylit::terrain
