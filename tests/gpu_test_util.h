// Shared fixtures of the GPU tests: a headless GL 4.5 context per test (skipped, with
// the reason, only where EGL cannot give one — CI's llvmpipe does — and failed there
// under SKYLIT_REQUIRE_GPU=1), and the two height fields the GPU-vs-reference
// comparisons run on.
#pragma once

#include "gpu/gl_context.h"
#include "lighting_test_util.h"
#include "shading/blockers/sphere_blocker.h"
#include "shading/lighting.h"
#include "terrain/dem_reader.h"
#include "terrain/height_field.h"
#include "terrain/synthetic.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace skylit::gpu::testing {

// SKYLIT_REQUIRE_GPU=1 (.ci/run sets it): a machine that cannot make a context fails the
// tests that need one, instead of passing them as skipped.
inline bool gpu_required() {
  const char* v = std::getenv("SKYLIT_REQUIRE_GPU");
  return v && std::string_view(v) == "1";
}

// A new context, or null with `why` set.
inline std::unique_ptr<HeadlessContext> try_context(std::string& why) {
  try {
    return std::make_unique<HeadlessContext>();
  } catch (const std::exception& e) {
    why = e.what();
    return nullptr;
  }
}

// Sets `ptr` (a std::unique_ptr<HeadlessContext>) to a new context, or ends the test:
// skipped with the reason, failed under SKYLIT_REQUIRE_GPU=1. In a test body or SetUp.
#define SKYLIT_CONTEXT_OR_SKIP(ptr)                                                                   \
  do {                                                                                                \
    std::string skylit_why_;                                                                          \
    (ptr) = ::skylit::gpu::testing::try_context(skylit_why_);                                         \
    if (!(ptr)) {                                                                                     \
      if (::skylit::gpu::testing::gpu_required()) FAIL() << "SKYLIT_REQUIRE_GPU=1: " << skylit_why_; \
      GTEST_SKIP() << "no OpenGL 4.5 context through EGL on this machine: " << skylit_why_;           \
    }                                                                                                 \
  } while (0)

class GpuTest : public ::testing::Test {
 protected:
  void SetUp() override { SKYLIT_CONTEXT_OR_SKIP(context); }
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

using skylit::testing::sun_at;  // lighting_test_util.h

// Gentle hills at 4 m texels (256 × 200 unless told), and a balloon-sized sphere 25 m above texel (i, j): a deep
// sky shadow whose reach (the cull budget's, ~320 m) covers a third of the field's width,
// and at a 30° sun a sun shadow ~45 m beside it (the frame-reuse tests).
inline terrain::HeightField hills(int width = 256, int height = 200) {
  terrain::SyntheticOptions o;
  o.width = width;
  o.height = height;
  o.spacing = 4.0;
  o.seed = 5;
  o.relief = 60.0;
  o.feature_size = 400.0;
  return terrain::make_synthetic_terrain(o);
}
inline std::vector<blockers::Sphere> balloon_over(const terrain::HeightField& f, int i, int j) {
  return {{{i * 4.0, -j * 4.0, f.at(i, j) + 25.0}, 10.0}};
}

}  // namespace skylit::gpu::testing
