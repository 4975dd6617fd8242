// Shared fixtures of the GPU tests: a headless GL 4.5 context per test (skipped, with
// the reason, only where EGL cannot give one — CI's llvmpipe does), and the two height
// fields the GPU-vs-reference comparisons run on.
#pragma once

#include "gpu/gl_context.h"
#include "terrain/dem_reader.h"
#include "terrain/height_field.h"
#include "terrain/synthetic.h"

#include <gtest/gtest.h>

#include <cstdint>
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

// Seeded synthetic mountains (ridges and a valley) on a non-square grid, with one
// nodata texel; the default is the fields most GPU tests compare on.
struct SyntheticFieldSpec {
  int width = 100, height = 88;
  std::uint64_t seed = 7;
  double feature_size = 2500.0, relief = 1400.0;  // m
  int nodata_i = 50, nodata_j = 40;
};

inline terrain::HeightField synthetic_field(const SyntheticFieldSpec& spec = {}) {
  terrain::SyntheticOptions o;
  o.width = spec.width;
  o.height = spec.height;
  o.spacing = 30.0;
  o.seed = spec.seed;
  o.feature_size = spec.feature_size;
  o.relief = spec.relief;
  terrain::HeightField f = terrain::make_synthetic_terrain(o);
  f.valid[static_cast<std::size_t>(spec.nodata_j) * f.width + spec.nodata_i] = 0;
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
