// Equirectangular HDR skies: an EXR with an analytic pattern written by
// OpenImageIO in a temporary directory, read back through EnvMapSky; the
// orientation convention, bilinear lookup, sun clamping and the rejections.
#include "shading/sky/sky_envmap.h"
#include "shading/sky/sky_sh.h"

#include <OpenImageIO/imageio.h>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <unistd.h>
#include <vector>

using namespace skylit::sky;
namespace fs = std::filesystem;

namespace {
constexpr double kPi = std::numbers::pi;

// Pattern in (east, north, up) components, positive everywhere.
Rgb pattern(double east, double north, double up) { return {1.0 + east, 1.0 + north, 2.0 + up}; }

class EnvMapTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("skylit_envmap_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Writes a w × h float RGB EXR whose texel (row, col) holds the pattern at the
  // direction of its centre, from the documented convention (row 0 = zenith,
  // column 0 = north, azimuth clockwise to the right), computed here independently.
  std::string write_exr(const std::string& name, int w, int h, double sun_value = 0.0) {
    std::vector<float> px(static_cast<std::size_t>(w) * h * 3);
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c) {
        const double theta = kPi * (r + 0.5) / h, az = 2 * kPi * (c + 0.5) / w;
        Rgb v = pattern(std::sin(theta) * std::sin(az), std::sin(theta) * std::cos(az), std::cos(theta));
        if (sun_value > 0 && r == h / 4 && c == w / 4) v = Rgb(sun_value);  // a one-texel "sun" due east
        for (int k = 0; k < 3; ++k) px[3 * (static_cast<std::size_t>(r) * w + c) + k] = static_cast<float>(v[k]);
      }
    const std::string path = (dir_ / name).string();
    auto out = OIIO::ImageOutput::create(path);
    EXPECT_TRUE(out);
    const OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::FLOAT);
    EXPECT_TRUE(out->open(path, spec));
    EXPECT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
    out->close();
    return path;
  }

  fs::path dir_;
};
}  // namespace

TEST_F(EnvMapTest, ReadsTexelsWithTheDocumentedOrientation) {
  const EnvMapSky sky = EnvMapSky::load(write_exr("pattern.exr", 64, 32));
  ASSERT_EQ(sky.width(), 64);
  ASSERT_EQ(sky.height(), 32);
  for (int r = 0; r < 16; ++r)
    for (int c = 0; c < 64; c += 7) {
      const glm::dvec3 d = sky.texel_direction(r, c);  // x east, y north, z up
      const Rgb want = pattern(d.x, d.y, d.z);
      const Rgb got = sky.radiance(d);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], 1e-6) << r << " " << c;
    }
  // Between texel centres the lookup is bilinear in angles: close to the smooth pattern.
  const glm::dvec3 ne = glm::normalize(glm::dvec3(0.6, 0.7, 0.4));
  const Rgb want = pattern(ne.x, ne.y, ne.z), got = sky.radiance(ne);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], 0.01);
  EXPECT_EQ(sky.radiance({0.3, 0.2, -0.5}), Rgb(0.0));  // lower half ignored
  // Left edge is north, a quarter across is east.
  EXPECT_NEAR(sky.texel_direction(15, 0).y, 1.0, 0.06);
  EXPECT_NEAR(sky.texel_direction(15, 16).x, 1.0, 0.06);
}

TEST_F(EnvMapTest, ScaleAndGreyIrradiance) {
  // A constant map: the horizontal irradiance is π·L whatever the resolution.
  std::vector<float> px(16 * 8 * 3, 0.25f);
  const EnvMapSky sky(16, 8, px, {.scale = 4.0});
  EXPECT_NEAR(horizontal_irradiance(sky).g, kPi, 1e-10);
  EXPECT_NEAR(horizontal_irradiance(project_sky(sky, 4)).b, kPi, 1e-10);
}

TEST_F(EnvMapTest, SunClampCapsTheBrightTexels) {
  const EnvMapSky raw = EnvMapSky::load(write_exr("sun.exr", 64, 32, 1e5));
  const EnvMapSky clamped = EnvMapSky::load(write_exr("sun2.exr", 64, 32, 1e5), {.sun_clamp = 50.0});
  EXPECT_NEAR(luminance(raw.texel(8, 16)), 1e5, 1.0);
  EXPECT_NEAR(luminance(clamped.texel(8, 16)), 50.0, 1e-4);
  EXPECT_EQ(clamped.texel(3, 3), raw.texel(3, 3));  // sky below the cap untouched
}

TEST_F(EnvMapTest, RejectsNonEquirectangularAndUnreadableFiles) {
  const std::string bad = write_exr("square.exr", 32, 32);
  try {
    EnvMapSky::load(bad);
    FAIL() << "accepted a 32 × 32 map";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("width = 2 × height"), std::string::npos) << e.what();
  }
  EXPECT_THROW(EnvMapSky::load((dir_ / "missing.exr").string()), std::runtime_error);
  const fs::path junk = dir_ / "junk.exr";
  std::ofstream(junk) << "not an image";
  EXPECT_THROW(EnvMapSky::load(junk.string()), std::runtime_error);
  EXPECT_THROW(EnvMapSky(10, 4, std::vector<float>(120, 1.0f)), std::invalid_argument);
  std::vector<float> nan(8 * 4 * 3, 1.0f);
  nan[5] = std::nanf("");
  EXPECT_THROW(EnvMapSky(8, 4, nan), std::invalid_argument);
}
