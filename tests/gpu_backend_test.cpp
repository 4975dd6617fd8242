// `skylit shade --backend gpu|auto|reference` end to end (app/shade/backend.cpp): the gpu
// backend writes the same products as the reference (tolerances of
// gpu_products_test), `auto` is the default and falls back to the reference where no
// GL 4.5 context exists, and `--backend gpu` without one fails with one clear line.
// Skipped when the skylit binary is not built or no context can be created (failed
// for want of a context under SKYLIT_REQUIRE_GPU=1).
#include <gtest/gtest.h>

#include <gdal.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "cli_test_util.h"
#include "gpu/gl_context.h"
#include "gpu_test_util.h"

namespace skylit::gpu {
namespace {

namespace fs = std::filesystem;
using skylit::testing::run_skylit;

class GpuBackendTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(SKYLIT_BINARY)) GTEST_SKIP() << "skylit binary not built: " << SKYLIT_BINARY;
    std::unique_ptr<HeadlessContext> probe;
    SKYLIT_CONTEXT_OR_SKIP(probe);
    dir = fs::temp_directory_path() / ("skylit_gpu_backend_" + std::to_string(::getpid()));
    fs::create_directories(dir);
  }
  void TearDown() override {
    if (!dir.empty()) fs::remove_all(dir);
  }
  std::string out(const std::string& name) const { return (dir / name).string(); }
  fs::path dir;
};

// All bands of a raster, band-major.
std::vector<float> read_bands(const std::string& path, int& width, int& height, int& bands) {
  GDALAllRegister();
  GDALDatasetH ds = GDALOpen(path.c_str(), GA_ReadOnly);
  if (!ds) return {};
  width = GDALGetRasterXSize(ds);
  height = GDALGetRasterYSize(ds);
  bands = GDALGetRasterCount(ds);
  std::vector<float> v(static_cast<std::size_t>(width) * height * bands);
  for (int b = 0; b < bands; ++b)
    if (GDALRasterIO(GDALGetRasterBand(ds, b + 1), GF_Read, 0, 0, width, height,
                     v.data() + static_cast<std::size_t>(b) * width * height, width, height, GDT_Float32, 0,
                     0) != CE_None)
      v.clear();
  GDALClose(ds);
  return v;
}

TEST_F(GpuBackendTest, GpuAndReferenceWriteTheSameProducts) {
  struct Case {
    const char* product;
    double tol;
  };
  // Tolerances as in gpu_products_test (float32 vs double); shaded: 8-bit codes.
  for (const Case& c : {Case{"horizon", 0.05}, Case{"svf", 2e-3}, Case{"skyview", 2e-3}, Case{"shaded", 1.0}}) {
    SCOPED_TRACE(c.product);
    // --no-sun: the uniform-sky `shaded` (lit products: the next test).
    const std::string common = std::string("shade --synthetic --size 48 --azimuths 8 -q --no-sun -p ") + c.product;
    ASSERT_EQ(run_skylit(common + " --backend gpu -o " + out(std::string(c.product) + "_gpu.tif")).status, 0);
    ASSERT_EQ(run_skylit(common + " --backend reference -o " + out(std::string(c.product) + "_ref.tif")).status, 0);
    int wg = 0, hg = 0, bg = 0, wr = 0, hr = 0, br = 0;
    const auto g = read_bands(out(std::string(c.product) + "_gpu.tif"), wg, hg, bg);
    const auto r = read_bands(out(std::string(c.product) + "_ref.tif"), wr, hr, br);
    ASSERT_FALSE(g.empty());
    ASSERT_EQ(g.size(), r.size());
    ASSERT_EQ(bg, br);
    // The outermost ring is left out (see gpu_products_test).
    std::size_t compared = 0, within = 0;
    for (int b = 0; b < bg; ++b)
      for (int j = 1; j < hg - 1; ++j)
        for (int i = 1; i < wg - 1; ++i) {
          const std::size_t t = (static_cast<std::size_t>(b) * hg + j) * wg + i;
          ++compared;
          within += std::abs(g[t] - r[t]) <= c.tol;
        }
    EXPECT_GE(static_cast<double>(within) / compared, 0.99);
    if (std::string(c.product) != "shaded") {
      EXPECT_EQ(within, compared);
    }
  }
}

// The lit products (sun shadow, sky tables) end to end; tolerances of gpu_lighting_test:
// shadow 0.02, irradiance 1e-3 relative (0.02·DNI in a penumbra), shaded 1 code, each on
// ≥ 99% of texels.
TEST_F(GpuBackendTest, LitProductsGpuMatchReferenceAndExactFallsBack) {
  struct Case {
    const char* product;
    const char* args;
    double abs_tol, rel_tol;
  };
  for (const Case& c : {Case{"shadow", " -az 135 -alt 10", 0.02, 0.0},
                        Case{"irradiance", " --sky preetham --sun-azimuth 300 --sun-elevation 30", 1e-3, 1e-3},
                        Case{"shaded", " --sky preetham -az 135 -alt 20", 1.0, 0.0}}) {
    SCOPED_TRACE(c.product);
    const std::string common =
        std::string("shade --synthetic --size 48 --azimuths 8 -q -p ") + c.product + c.args;
    const std::string g_path = out(std::string(c.product) + "_lit_gpu.tif");
    const std::string r_path = out(std::string(c.product) + "_lit_ref.tif");
    ASSERT_EQ(run_skylit(common + " --backend gpu -o " + g_path).status, 0);
    ASSERT_EQ(run_skylit(common + " --backend reference -o " + r_path).status, 0);
    int wg = 0, hg = 0, bg = 0, wr = 0, hr = 0, br = 0;
    const auto g = read_bands(g_path, wg, hg, bg);
    const auto r = read_bands(r_path, wr, hr, br);
    ASSERT_FALSE(g.empty());
    ASSERT_EQ(g.size(), r.size());
    ASSERT_EQ(bg, br);
    std::size_t within = 0;
    for (std::size_t t = 0; t < g.size(); ++t) within += std::abs(g[t] - r[t]) <= c.abs_tol + c.rel_tol * std::abs(r[t]);
    EXPECT_GE(static_cast<double>(within) / g.size(), 0.99);
  }
  // The sun's exact march is CPU-only: gpu refuses in one line, auto falls back.
  const std::string exact = "shade --synthetic --size 16 --azimuths 4 -q -p shadow --exact -o ";
  const auto refused = run_skylit(exact + out("e_gpu.tif") + " --backend gpu", true);
  EXPECT_NE(refused.status, 0);
  EXPECT_NE(refused.out.find("--exact"), std::string::npos) << refused.out;
  EXPECT_EQ(run_skylit(exact + out("e_auto.tif")).status, 0);
  EXPECT_TRUE(fs::exists(out("e_auto.tif")));
}

TEST_F(GpuBackendTest, AutoIsTheDefaultAndGpuWithoutContextFailsInOneLine) {
  const auto help = run_skylit("shade --help", true);
  EXPECT_NE(help.out.find("--backend TEXT=auto"), std::string::npos) << help.out;

  // glvnd's EGL finds no vendor library with this: no context can be created.
  const std::string no_egl = "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json ";
  const std::string cmd = std::string("shade --synthetic --size 16 --azimuths 4 -q -p svf -o ");
  {
    const std::string probe =
        "env " + no_egl + SKYLIT_BINARY + " " + cmd + out("probe.tif") + " --backend gpu 2>/dev/null";
    if (std::system(probe.c_str()) == 0) GTEST_SKIP() << "EGL still works with no vendor library (no glvnd)";
  }
  // run_skylit prefixes the binary; put the environment in front with `env` instead.
  const std::string bin = SKYLIT_BINARY;
  auto run_env = [&](const std::string& args) {
    const std::string full = "env " + no_egl + bin + " " + args + " 2>&1";
    FILE* pipe = popen(full.c_str(), "r");
    std::string text;
    char buf[4096];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0) text.append(buf, n);
    const int raw = pclose(pipe);
    return std::make_pair(WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, text);
  };
  const auto [gpu_status, gpu_text] = run_env(cmd + out("g.tif") + " --backend gpu");
  EXPECT_NE(gpu_status, 0);
  EXPECT_EQ(skylit::testing::count_lines(gpu_text), 1) << gpu_text;
  EXPECT_NE(gpu_text.find("--backend gpu: no OpenGL 4.5 context"), std::string::npos) << gpu_text;
  EXPECT_FALSE(fs::exists(out("g.tif")));

  const auto [auto_status, auto_text] = run_env(cmd + out("a.tif"));
  EXPECT_EQ(auto_status, 0) << auto_text;
  EXPECT_TRUE(fs::exists(out("a.tif")));
}

}  // namespace
}  // namespace skylit::gpu
