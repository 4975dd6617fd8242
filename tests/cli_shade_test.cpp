// `skylit shade` end to end: every product on small rasters with georeferencing
// kept, and every kind of bad input rejected with one clear line, a non-zero
// exit and no output file left behind.
#include "cli_test_util.h"
#include "gpu_test_util.h"
#include "terrain_test_util.h"

#include "shading/quality.h"

#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <utility>

using skylit::testing::count_lines;
using skylit::testing::OutputRaster;
using skylit::testing::read_output;
using skylit::testing::run_skylit;
using skylit::testing::expect_clean_shade_failure;
using namespace skylit::terrain::testing;

namespace {

// A 24×20 projected DEM: a Gaussian hill on a plane, 30 m pixels, UTM 11N.
std::string make_hill(const ScratchDir& dir, const std::string& name = "hill.tif") {
  RasterSpec s;
  s.width = 24;
  s.height = 20;
  s.values.resize(24 * 20);
  for (int j = 0; j < 20; ++j)
    for (int i = 0; i < 24; ++i)
      s.values[j * 24 + i] = 500 + 300 * std::exp(-((i - 12) * (i - 12) + (j - 10) * (j - 10)) / 20.0);
  return make_raster(dir.file(name), s);
}


}  // namespace

TEST(CliShade, EveryProductKeepsGeoreferencing) {
  ScratchDir dir;
  const std::string in = make_hill(dir);
  for (const std::string product : {"svf", "skyview", "horizon", "shaded"}) {
    const std::string out = dir.file(product + (product == "shaded" ? ".png" : ".tif"));
    const auto r = run_skylit("shade " + in + " -o " + out + " --product " + product + " --azimuths 8 -q", true);
    ASSERT_EQ(r.status, 0) << r.out;
    const OutputRaster o = read_output(out);
    EXPECT_EQ(o.w, 24);
    EXPECT_EQ(o.h, 20);
    EXPECT_EQ(o.bands, product == "horizon" ? 8 : 1);
    EXPECT_EQ(o.type, product == "shaded" ? GDT_Byte : GDT_Float32);
    if (product != "shaded") {
      EXPECT_DOUBLE_EQ(o.gt[0], 500000);
      EXPECT_DOUBLE_EQ(o.gt[1], 30);
      EXPECT_DOUBLE_EQ(o.gt[3], 4000000);
      EXPECT_NE(o.crs_name.find("UTM zone 11N"), std::string::npos) << o.crs_name;
    }
  }
}

TEST(CliShade, NodataIsKeptInOutputs) {
  ScratchDir dir;
  RasterSpec s;
  s.width = s.height = 16;
  s.values = ramp(16, 16, 100, 3, 1);
  s.values[5 * 16 + 7] = -32768;
  s.nodata = -32768;
  const std::string in = make_raster(dir.file("void.tif"), s);
  const std::string out = dir.file("svf.tif");
  ASSERT_EQ(run_skylit("shade " + in + " -o " + out + " -p svf --azimuths 8 -q").status, 0);
  const OutputRaster o = read_output(out);
  ASSERT_TRUE(o.has_nodata);
  ASSERT_EQ(o.w, 16);
  const std::vector<float>& v = o.v;
  int nodata = 0;
  for (int k = 0; k < 256; ++k) {
    if (v[k] == static_cast<float>(o.nodata)) ++nodata;
    else EXPECT_TRUE(v[k] > 0.0f && v[k] <= 1.0f) << k << ": " << v[k];
  }
  EXPECT_EQ(nodata, 1);
  EXPECT_EQ(v[5 * 16 + 7], static_cast<float>(o.nodata));
}

TEST(CliShade, BuiltInSceneWritesPng) {
  ScratchDir dir;
  const std::string out = dir.file("default.png");
  const auto r = run_skylit("shade --synthetic --size 64 --azimuths 8 -o " + out + " -q", true);
  ASSERT_EQ(r.status, 0) << r.out;
  const OutputRaster o = read_output(out);
  EXPECT_EQ(o.w, 64);
  EXPECT_EQ(o.type, GDT_Byte);
}

TEST(CliShade, SaysWhichBackendComputed) {
  ScratchDir dir;
  const auto r = run_skylit("shade --synthetic --size 16 --azimuths 4 -p svf --backend reference -o " + dir.file("s.tif"), true);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("skylit: computed on reference (CPU)"), std::string::npos) << r.out;
  const auto g = run_skylit("shade --synthetic --size 16 --azimuths 4 -p svf -o " + dir.file("g.tif"), true);
  ASSERT_EQ(g.status, 0) << g.out;
  // auto falls back where no context exists, and says so; not under SKYLIT_REQUIRE_GPU=1.
  const bool gpu = g.out.find("skylit: computed on gpu (") != std::string::npos;
  const bool fallback = g.out.find("skylit: computed on reference (CPU; no OpenGL 4.5 context)") != std::string::npos;
  EXPECT_TRUE(gpu || (fallback && !skylit::gpu::testing::gpu_required())) << g.out;
}

// --timings: one line per stage, also with -q, and the stages of the backend that ran.
TEST(CliShade, TimingsNameEveryStage) {
  ScratchDir dir;
  const auto r = run_skylit("shade --synthetic --size 16 --azimuths 4 -p svf --backend reference -q --timings -o " +
                                dir.file("s.tif"),
                            true);
  ASSERT_EQ(r.status, 0) << r.out;
  for (const char* stage : {"time read DEM", "time compute (CPU reference)", "time write output"})
    EXPECT_NE(r.out.find(stage), std::string::npos) << stage << "\n" << r.out;
  EXPECT_EQ(r.out.find("pyramid build"), std::string::npos) << "no GPU stages on the reference\n" << r.out;
  const auto g = run_skylit("shade --synthetic --size 16 --azimuths 4 -p svf -q --timings -o " + dir.file("g.tif"), true);
  ASSERT_EQ(g.status, 0) << g.out;
  EXPECT_NE(g.out.find("time write output"), std::string::npos) << g.out;
  if (g.out.find("compute (all GPU stages)") != std::string::npos) {
    for (const char* stage : {"time OpenGL context", "time compile kernels", "time pyramid build", "time horizon sweep"})
      EXPECT_NE(g.out.find(stage), std::string::npos) << stage << "\n" << g.out;
  }
}

TEST(CliShade, BadInputFailsCleanly) {
  ScratchDir dir;
  const std::string hill = make_hill(dir);
  const std::string out = " -o " + dir.file("out.tif");
  expect_clean_shade_failure(dir, dir.file("missing.tif") + out, "missing.tif");
  {
    std::ofstream(dir.file("notes.txt")) << "not a raster at all\n";
    expect_clean_shade_failure(dir, dir.file("notes.txt") + out, "notes.txt");
  }
  {
    std::ofstream f(dir.file("corrupt.tif"), std::ios::binary);
    f << "II*\0garbage that is not a TIFF directory";
  }
  expect_clean_shade_failure(dir, dir.file("corrupt.tif") + out, "corrupt.tif");

  auto raster = [&](const std::string& name, RasterSpec s) { return make_raster(dir.file(name), s); };
  RasterSpec all_void;
  all_void.values.assign(16, -9999);
  all_void.nodata = -9999;
  expect_clean_shade_failure(dir, raster("void.tif", all_void) + out, "nodata");
  RasterSpec nan_h;
  nan_h.values = ramp(4, 4, 10, 1, 1);
  nan_h.values[5] = std::numeric_limits<double>::infinity();
  expect_clean_shade_failure(dir, raster("inf.tif", nan_h) + out, "inf.tif");
  RasterSpec absurd;
  absurd.values = ramp(4, 4, 10, 1, 1);
  absurd.values[3] = 25000;
  expect_clean_shade_failure(dir, raster("absurd.tif", absurd) + out, "absurd.tif");
  RasterSpec one;
  one.width = one.height = 1;
  expect_clean_shade_failure(dir, raster("one.tif", one) + out, "one.tif");
  RasterSpec strip;
  strip.width = 9;
  strip.height = 1;
  expect_clean_shade_failure(dir, raster("strip.tif", strip) + out, "strip.tif");
  RasterSpec rotated;
  rotated.gt = {500000, 30, 5, 4000000, 5, -30};
  expect_clean_shade_failure(dir, raster("rotated.tif", rotated) + out, "rotated.tif");
  RasterSpec no_crs;
  no_crs.epsg.reset();
  no_crs.set_geotransform = false;
  const std::string nocrs = raster("nocrs.tif", no_crs);
  expect_clean_shade_failure(dir, nocrs + out, "-s/--scale");

  // Output problems are found before any work.
  expect_clean_shade_failure(dir, hill + " -o " + dir.file("no/such/folder/out.tif"), "does not exist");
  expect_clean_shade_failure(dir, hill + " -o " + dir.file("out.png") + " -p svf", "PNG");
  expect_clean_shade_failure(dir, hill + " -o " + dir.file("out.xyz"), "format");
  expect_clean_shade_failure(dir, hill + out + " -p bogus", "bogus");
  expect_clean_shade_failure(dir, hill + out + " --backend cuda", "cuda");
  // Options bounded by their sign say so in a short line (CLI11's own checks print their
  // range up to DBL_MAX, 300 digits).
  for (const auto& [arg, needle] : {std::pair{" --zfactor 0", "--zfactor: must be greater than 0, not 0"},
                                    std::pair{" --max-distance -5", "--max-distance: must be 0 or more, not -5"},
                                    std::pair{" --exposure nan", "--exposure: expected a finite number, not 'nan'"},
                                    std::pair{" --xscale ten", "--xscale: expected a number, not 'ten'"},
                                    std::pair{" --threads -1", "--threads: must be 0 or more, not -1"}}) {
    expect_clean_shade_failure(dir, hill + out + arg, needle);
    EXPECT_LT(run_skylit("shade " + hill + out + arg, true).out.size(), 120u) << arg;
  }
  expect_clean_shade_failure(dir, out, "INPUT");
  expect_clean_shade_failure(dir, hill + " " + hill + " " + dir.file("out.tif") + " --synthetic" + out, "--synthetic");
}

TEST(CliShade, UnknownCrsWorksOnlyWithAScale) {
  ScratchDir dir;
  const std::string in = make_crs_less_ramp(dir.file("nocrs.tif"));
  const auto r = run_skylit("shade " + in + " -s 10 -o " + dir.file("svf.tif") + " -p svf --azimuths 4", true);
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("warning"), std::string::npos) << r.out;
}

TEST(CliShade, RefusesToOverwriteWithoutFlagAndFailsOnReadOnlyFolder) {
  ScratchDir dir;
  const std::string in = make_hill(dir);
  const std::string out = dir.file("svf.tif");
  ASSERT_EQ(run_skylit("shade " + in + " -o " + out + " -p svf --azimuths 4 -q").status, 0);
  expect_clean_shade_failure(dir, in + " -o " + out + " -p svf", "--overwrite");
  EXPECT_EQ(run_skylit("shade " + in + " -o " + out + " -p svf --azimuths 4 -q --overwrite").status, 0);
  if (::geteuid() != 0) {  // root ignores folder permissions
    std::filesystem::create_directory(dir.file("ro"));
    std::filesystem::permissions(dir.file("ro"), std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
    expect_clean_shade_failure(dir, in + " -o " + dir.file("ro/out.tif"), "not writable");
  }
  // A folder nobody can create files in, root included.
  expect_clean_shade_failure(dir, in + " -o /proc/skylit_out.tif -p svf", "/proc/skylit_out.tif");
}

TEST(CliShade, HelpAndVersion) {
  const auto help = run_skylit("--help");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.out.find("shade"), std::string::npos);
  const auto v = run_skylit("--version");
  EXPECT_EQ(v.status, 0);
  EXPECT_NE(v.out.find("skylit "), std::string::npos);
}

TEST(CliShade, QualityPresetSetsKnobsAndExplicitFlagsWin) {
  ScratchDir dir;
  const std::string in = make_hill(dir);
  auto bands = [&](const std::string& extra) {
    const std::string out = dir.file("h.tif");
    const auto r = run_skylit("shade " + in + " -o " + out + " -p horizon --overwrite -q " + extra, true);
    EXPECT_EQ(r.status, 0) << r.out;
    return read_output(out).bands;
  };
  // Azimuth counts of the presets, from the library (shading/quality.h).
  EXPECT_EQ(bands("--quality fast"), skylit::shading::quality_settings(skylit::shading::Quality::Fast).azimuths);
  EXPECT_EQ(bands("--quality high"), skylit::shading::quality_settings(skylit::shading::Quality::High).azimuths);
  EXPECT_EQ(bands("--quality fast --azimuths 8"), 8);
  // The march knobs of a preset, and explicit flags over them (horizons in degrees).
  auto values = [&](const std::string& extra) {
    const std::string out = dir.file("v.tif");
    EXPECT_EQ(run_skylit("shade " + in + " -o " + out + " -p horizon --overwrite -q " + extra, true).status, 0);
    return read_output(out).v;
  };
  const auto fast = values("--quality fast");
  EXPECT_EQ(fast, values("--azimuths 16"));  // the default sweep's knobs at W 16
  EXPECT_NE(fast, values("--quality fast --near-steps 2"));
  const auto fast_march = values("--quality fast --horizons march");
  EXPECT_EQ(fast_march, values("--horizons march --azimuths 16 --levels bilinear --horizon-max plain"));
  EXPECT_NE(fast_march, values("--quality fast --horizons march --levels bspline --horizon-max smooth"));
  EXPECT_EQ(values("--quality fast --horizons march --levels bspline --horizon-max smooth"),
            values("--horizons march --azimuths 16 --levels bspline --horizon-max smooth"));
  expect_clean_shade_failure(dir, in + " -o " + dir.file("x.tif") + " --quality best", "--quality");
}
