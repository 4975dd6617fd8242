// Shared fixtures of the GPU tests: a headless GL 4.5 context per test (skipped, with
// the reason, only where EGL cannot give one — CI's llvmpipe does), and the two height
// fields the GPU-vs-reference comparisons run on.
#pragma once

#include "gpu/gl_context.h"
#include "terrain/dem_reader.h"
#include "terrain/height_field.h"
#include "terrain/synthetic.h"

#include <gtest/gtest.h>

#include <exception>
#include <filesystem>
#include <memory>
#include <string>

namespace skylit::gpu::testing {

class GpuTest : public ::testing::Test {
 protected:
  void SetUp() override {
    try {
      context = std::make_unique<HeadlessContext>();
    } catch (const std::exception& e) {
      GTEST_SKIP() << "no OpenGL 4.5 context through EGL on this machine: " << e.what();
    }
  }
  std::unique_ptr<HeadlessContext> context;
};

// Seeded synthetic mountains (ridges and a valley) on a non-square grid, with a
// nodata texel.
inline terrain::HeightField synthetic_field() {
  terrain::SyntheticOptions o;
  o.width = 100;
  o.height = 88;
  o.spacing = 30.0;
  o.seed = 7;
  o.feature_size = 2500.0;
  o.relief = 1400.0;
  terrain::HeightField f = terrain::make_synthetic_terrain(o);
  f.valid[static_cast<std::size_t>(40) * f.width + 50] = 0;
  return f;
}

// A 104 × 88 crop of the Cascades SRTM 1″ DEM (geographic: per-row dx ≈ 21 m, dy ≈ 31 m);
// false where ../shared/dem is absent.
inline bool real_dem(terrain::HeightField& out) {
  const std::string path = std::string(SKYLIT_SHARED_DIR) + "/dem/cascades_skykomish_srtm1_4326.tif";
  if (!std::filesystem::exists(path)) return false;
  terrain::DemReadOptions o;
  o.window = terrain::PixelRect{300, 130, 104, 88};
  out = terrain::read_dem(path, o).field;
  return true;
}

}  // namespace skylit::gpu::testing
