// gpu/field_limits.h: the largest field one GPU frame takes. On Mesa's llvmpipe the
// limits were measured by running the pipeline (docs/performance.md, "field size"):
// 5792² ran and 5793² stopped at the heights' storage block at k_v = 4; 4621² ran and
// 4622² stopped at the pyramid's texture buffer at k_v = 8.
#include "gpu/field_limits.h"

#include "gpu/buffers.h"
#include "gpu/gpu_renderer.h"
#include "gpu_test_util.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <string>

namespace {

using skylit::shading::Product;
using skylit::shading::ProductOptions;
using FieldLimits = skylit::gpu::testing::GpuTest;

ProductOptions bounded(int k_v) {
  ProductOptions o;
  o.march.k_v = k_v;
  o.march.max_distance_m = 5000;
  o.march.method = skylit::horizon::HorizonMethod::March;  // no sweep-line limit
  return o;
}

bool on_llvmpipe() {
  const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return name && std::string(name).find("llvmpipe") != std::string::npos;
}

TEST_F(FieldLimits, TheLargestSquareIsTheLastThatFits) {
  skylit::gpu::GpuRenderer renderer;
  for (int k_v : {4, 8}) {
    const auto side = skylit::shading::max_square_side(renderer, Product::Svf, bounded(k_v));
    ASSERT_TRUE(side);
    EXPECT_TRUE(skylit::gpu::field_fits_gpu(*side, *side, Product::Svf, bounded(k_v)));
    EXPECT_FALSE(skylit::gpu::field_fits_gpu(*side + 1, *side + 1, Product::Svf, bounded(k_v)));
    // The heights' block, as the pipeline checks it, holds the side.
    EXPECT_NO_THROW(skylit::gpu::check_storage_size(std::size_t(*side) * *side * sizeof(float), "heights"));
    if (on_llvmpipe()) {
      EXPECT_EQ(*side, k_v == 4 ? 5792 : 4621) << "k_v " << k_v;
    }
  }
  // Host-side products have no GPU limit.
  EXPECT_FALSE(skylit::shading::max_square_side(renderer, Product::Hillshade, bounded(4)));
}

TEST_F(FieldLimits, ASweepIsBoundedByItsLines) {
  ProductOptions o;  // the default: sweep, unbounded distance
  GLint size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &size);
  const int side = (size + 1) / 2;  // a line of 2·side − 1 samples
  EXPECT_TRUE(skylit::gpu::field_fits_gpu(side, 16, Product::Svf, o));
  EXPECT_FALSE(skylit::gpu::field_fits_gpu(side + 1, 16, Product::Svf, o));
  EXPECT_TRUE(skylit::gpu::field_fits_gpu(side + 1, 16, Product::Svf, bounded(4)));
}

}  // namespace
