// skylit shade -p color-relief against gdaldem color-relief (run here, on crops of the shared
// DEMs): every pixel of every band must be equal. Without gdaldem or ../shared the tests skip,
// and fail under CI.
#include "cli_test_util.h"

#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <vector>

namespace {

namespace fs = std::filesystem;
using skylit::testing::run_skylit;

bool ci() { return std::getenv("CI") != nullptr; }

#define REQUIRE_OR_SKIP(cond, why)      \
  do {                                  \
    if (!(cond)) {                      \
      if (ci()) FAIL() << why;          \
      GTEST_SKIP() << why;              \
    }                                   \
  } while (0)

std::vector<std::uint8_t> read_bytes(const fs::path& p, int& bands) {
  GDALAllRegister();
  GDALDataset* d = static_cast<GDALDataset*>(GDALOpen(p.c_str(), GA_ReadOnly));
  if (!d) return {};
  bands = d->GetRasterCount();
  const int w = d->GetRasterXSize(), h = d->GetRasterYSize();
  std::vector<std::uint8_t> v(static_cast<std::size_t>(bands) * w * h);
  if (d->RasterIO(GF_Read, 0, 0, w, h, v.data(), w, h, GDT_Byte, bands, nullptr, 0, 0, 0) != CE_None) v.clear();
  GDALClose(d);
  return v;
}

class ColorReliefCli : public ::testing::Test {
 protected:
  fs::path dir;
  void SetUp() override {
    dir = fs::temp_directory_path() / ("skylit_color_relief_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    write("plain.txt", "# plain, all separators\n1000 0 128 0\n1500,200,180,100\n2000:255:255:255\n2500\twhite\n");
    write("nv.txt", "nv 10 20 30\n0 0 0 255\n200 0 255 0\n800 brown\n2000 255 255 255\n");
    write("pct.txt", "0% 0 0 255\n37.5% yellow\n100% 255 0 0\n");
    write("alpha.txt", "nv 0 0 0 0\n0 0 0 255 100\n1500 200 100 0 200\n3000 255 255 255 255\n");
    write("steps.txt", "500 10 10 10\n1000 50 60 70\n1000 90 90 90\n1800 200 210 220\n");
    write("t.cpt", "# COLOR_MODEL = RGB\n0 0 0 255 500 0 255 0\n500 0 255 0 3000 255 255 255\n"
                   "B 0 0 0\nF 255 255 255\nN 128 128 128\n");
  }
  void TearDown() override { fs::remove_all(dir); }
  void write(const std::string& name, const std::string& text) { std::ofstream(dir / name) << text; }

  // Crops `dem` (gdal_translate -srcwin) to dir/name.
  bool crop(const std::string& dem, const std::string& srcwin, const std::string& name) {
    const std::string cmd = "gdal_translate -q -srcwin " + srcwin + " " + dem + " " + (dir / name).string();
    return std::system(cmd.c_str()) == 0;
  }

  void expect_same(const std::string& dem, const std::string& table, const std::string& gdal_flags,
                   const std::string& skylit_flags) {
    const fs::path g = dir / "g.tif", s = dir / "s.tif", src = dir / dem, col = dir / table;
    fs::remove(g);
    const std::string gcmd = "gdaldem color-relief -q " + gdal_flags + " " + src.string() + " " + col.string() +
                             " " + g.string() + " >/dev/null 2>&1";
    ASSERT_EQ(std::system(gcmd.c_str()), 0) << gcmd;
    fs::remove(src.string() + ".aux.xml");  // gdaldem's statistics must not feed skylit's percentages
    const auto run = run_skylit("shade -q " + src.string() + " -p color-relief --color " + col.string() + " " +
                                skylit_flags + " -o " + s.string() + " --overwrite", true);
    ASSERT_EQ(run.status, 0) << run.out;
    int gb = 0, sb = 0;
    const auto gv = read_bytes(g, gb), sv = read_bytes(s, sb);
    ASSERT_EQ(gb, sb);
    ASSERT_EQ(gv.size(), sv.size());
    ASSERT_FALSE(gv.empty());
    std::size_t diff = 0;
    for (std::size_t k = 0; k < gv.size(); ++k) diff += gv[k] != sv[k];
    EXPECT_EQ(diff, 0u) << dem << " " << table << " " << gdal_flags << ": " << diff << " of " << gv.size();
  }
};

TEST_F(ColorReliefCli, MatchesGdaldemBitForBit) {
  REQUIRE_OR_SKIP(std::system("command -v gdaldem >/dev/null 2>&1") == 0, "gdaldem is not installed");
  const std::string shared = SKYLIT_SHARED_DIR "/dem/";
  REQUIRE_OR_SKIP(fs::exists(shared + "pyrenees_andorra_srtm3_4326.tif"), "../shared/dem is missing");
  ASSERT_TRUE(crop(shared + "pyrenees_andorra_srtm3_4326.tif", "100 100 300 300", "pyr.tif"));
  ASSERT_TRUE(crop(shared + "nice_monaco_coast_srtm3_4326.tif", "0 0 300 300", "nice.tif"));  // sea, nodata
  ASSERT_TRUE(crop(shared + "mt_st_helens_usgs30_utm10n.tif", "200 200 300 300", "msh.tif"));
  for (const char* dem : {"pyr.tif", "nice.tif", "msh.tif"})
    for (const char* table : {"plain.txt", "nv.txt", "pct.txt", "alpha.txt", "steps.txt", "t.cpt"}) {
      expect_same(dem, table, "", "");
      expect_same(dem, table, "-alpha", "--alpha");
      expect_same(dem, table, "-exact_color_entry -alpha", "--exact-color-entry --alpha");
      expect_same(dem, table, "-nearest_color_entry", "--nearest-color-entry");
    }
}

TEST_F(ColorReliefCli, ShippedRampsRenderAsTheirFiles) {
  REQUIRE_OR_SKIP(std::system("command -v gdaldem >/dev/null 2>&1") == 0, "gdaldem is not installed");
  const std::string shared = SKYLIT_SHARED_DIR "/dem/";
  REQUIRE_OR_SKIP(fs::exists(shared + "nice_monaco_coast_srtm3_4326.tif"), "../shared/dem is missing");
  ASSERT_TRUE(crop(shared + "nice_monaco_coast_srtm3_4326.tif", "0 0 300 300", "nice.tif"));
  for (const std::string ramp : {"hypsometric", "grey", "bathymetry"}) {
    fs::copy_file(SKYLIT_SOURCE_DIR "/data/ramps/" + ramp + ".txt", dir / (ramp + ".txt"),
                  fs::copy_options::overwrite_existing);
    const fs::path by_name = dir / "n.tif";
    const auto run = run_skylit("shade -q " + (dir / "nice.tif").string() + " -p color-relief --alpha --color " + ramp +
                                " -o " + by_name.string() + " --overwrite", true);
    ASSERT_EQ(run.status, 0) << run.out;
    expect_same("nice.tif", ramp + ".txt", "-alpha", "--alpha");
    int nb = 0, fb = 0;
    EXPECT_EQ(read_bytes(by_name, nb), read_bytes(dir / "s.tif", fb)) << ramp;
  }
  const auto bad = run_skylit("shade -q " + (dir / "nice.tif").string() + " -p color-relief --color nope -o " +
                              (dir / "x.tif").string(), true);
  EXPECT_NE(bad.status, 0);
  EXPECT_NE(bad.out.find("hypsometric, grey, bathymetry"), std::string::npos) << bad.out;
  EXPECT_FALSE(fs::exists(dir / "x.tif"));
}

// Tinted relief = the formulas (written out here) applied to skylit's own grey `shaded` and
// gdaldem's colour relief of the same DEM, per pixel, equal code values.
TEST_F(ColorReliefCli, TintedReliefIsTheBlendOfShadedAndGdaldemColours) {
  REQUIRE_OR_SKIP(std::system("command -v gdaldem >/dev/null 2>&1") == 0, "gdaldem is not installed");
  const std::string shared = SKYLIT_SHARED_DIR "/dem/";
  REQUIRE_OR_SKIP(fs::exists(shared + "pyrenees_andorra_srtm3_4326.tif"), "../shared/dem is missing");
  ASSERT_TRUE(crop(shared + "pyrenees_andorra_srtm3_4326.tif", "100 100 120 120", "t.tif"));
  const std::string ramp = SKYLIT_SOURCE_DIR "/data/ramps/bathymetry.txt";  // metres: no range coupling
  const std::string src = (dir / "t.tif").string();
  ASSERT_EQ(std::system(("gdaldem color-relief -q " + src + " " + ramp + " " + (dir / "c.tif").string()).c_str()), 0);
  ASSERT_EQ(run_skylit("shade -q " + src + " -p shaded -o " + (dir / "g.tif").string()).status, 0);
  int nc = 0, ng = 0, nm = 0, ns = 0;
  const auto colour = read_bytes(dir / "c.tif", nc), grey = read_bytes(dir / "g.tif", ng);
  ASSERT_EQ(run_skylit("shade -q " + src + " -p shaded --color " + ramp + " --tint-blend multiply -o " +
                       (dir / "m.tif").string()).status, 0);
  ASSERT_EQ(run_skylit("shade -q " + src + " -p shaded --color " + ramp + " --tint-blend soft-light:0.7 -o " +
                       (dir / "s.tif").string()).status, 0);
  ASSERT_EQ(run_skylit("shade -q " + src + " -p shaded --color " + ramp + " -o " + (dir / "d.tif").string()).status, 0);
  int nd = 0;
  const auto dflt = read_bytes(dir / "d.tif", nd);  // the default blend, multiply:0.75
  const auto mul = read_bytes(dir / "m.tif", nm), soft = read_bytes(dir / "s.tif", ns);
  ASSERT_EQ(ng, 1);
  ASSERT_EQ(nm, 3);
  ASSERT_EQ(ns, 3);
  const std::size_t plane = grey.size();
  const auto code = [](double x) { return 1.0 + std::round(254.0 * std::clamp(x, 0.0, 1.0)); };  // display values
  int checked = 0;
  for (std::size_t k = 0; k < plane; ++k) {
    if (grey[k] == 0) continue;  // nodata
    const double g = (grey[k] - 1.0) / 254.0;
    for (int b = 0; b < 3; ++b) {
      const double c = colour[b * plane + k] / 255.0;
      EXPECT_NEAR(mul[b * plane + k], code(c * g), 0.0) << k;
      EXPECT_NEAR(dflt[b * plane + k], code(c * (0.25 + 0.75 * g)), 0.0) << k;
      const double d = c <= 0.25 ? ((16 * c - 12) * c + 4) * c : std::sqrt(c);
      const double sl = g <= 0.5 ? c - (1 - 2 * g) * c * (1 - c) : c + (2 * g - 1) * (d - c);
      EXPECT_NEAR(soft[b * plane + k], code(0.7 * sl + 0.3 * c), 0.0) << k;
      ++checked;
    }
  }
  EXPECT_GT(checked, 3 * 100 * 100);
}

TEST_F(ColorReliefCli, BadLineNamesFileAndLine) {
  REQUIRE_OR_SKIP(std::system("command -v gdal_translate >/dev/null 2>&1") == 0, "gdal_translate is not installed");
  const std::string shared = SKYLIT_SHARED_DIR "/dem/";
  REQUIRE_OR_SKIP(fs::exists(shared + "pyrenees_andorra_srtm3_4326.tif"), "../shared/dem is missing");
  ASSERT_TRUE(crop(shared + "pyrenees_andorra_srtm3_4326.tif", "0 0 50 50", "small.tif"));
  write("bad.txt", "# ok\n100 0 0 0\n200 12 x 4\n");
  const fs::path out = dir / "o.tif";
  const auto run = run_skylit("shade -q " + (dir / "small.tif").string() + " -p color-relief --color " +
                              (dir / "bad.txt").string() + " -o " + out.string(), true);
  EXPECT_NE(run.status, 0);
  EXPECT_NE(run.out.find((dir / "bad.txt").string() + ":3:"), std::string::npos) << run.out;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
