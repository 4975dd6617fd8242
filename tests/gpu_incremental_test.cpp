// The dynamic height field on the GPU (gpu/resident_field.h): GpuProductPipeline keeps
// the field resident between compute() calls, so after an edit (terrain/editing.h)
// only the edited rows of heights and valid mask are uploaded, and the pyramid is
// rebuilt on the GPU from them. Checked: the result equals a fresh pipeline's on the
// edited field bit for bit (same kernels on the same GPU data), matches the CPU
// reference within gpu_products_test's svf tolerance (2e-3, derived there), and
// GpuPipelineTimings::uploaded_bytes is exactly the edited rows' bytes. Another field,
// or several edits since, is uploaded whole.
// Runs on Mesa llvmpipe where there is no GPU.
#include "gpu_test_util.h"
#include "gpu_tolerances.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <optional>
#include <vector>

#include "gpu/gpu_pipeline.h"
#include "shading/products.h"
#include "terrain/editing.h"

namespace skylit::gpu {
namespace {

using shading::Product;
using shading::ProductBands;
using terrain::HeightField;
using terrain::PixelRect;

using namespace tolerance;  // gpu_tolerances.h

using GpuIncrementalTest = testing::GpuTest;

// Bytes of rows y0 … y1 − 1: float heights, plus the 32-bit words of the valid mask
// (1 byte per texel, 4 per word) that hold them.
std::size_t row_bytes(const HeightField& f, const PixelRect& r) {
  const std::size_t first = static_cast<std::size_t>(r.y0) * f.width, end = static_cast<std::size_t>(r.y1()) * f.width;
  return (end - first) * sizeof(float) + ((end + 3) / 4 - first / 4) * sizeof(std::uint32_t);
}

std::size_t whole_bytes(const HeightField& f) {
  return f.size() * sizeof(float) + (f.size() + 3) / 4 * sizeof(std::uint32_t) + f.height * sizeof(float);
}

bool bit_identical(const ProductBands& a, const ProductBands& b) {
  return a.data.size() == b.data.size() && std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)) == 0;
}

// A raised block: heights + 300 m over `r` (and valid there, as replace_heights makes it).
void raise(HeightField& f, const PixelRect& r) {
  std::vector<float> v;
  for (int j = r.y0; j < r.y1(); ++j)
    for (int i = r.x0; i < r.x1(); ++i) v.push_back(f.at(i, j) + 300.0f);
  terrain::replace_heights(f, r, v);
}

TEST_F(GpuIncrementalTest, EditUploadsOnlyItsRowsAndMatchesAFreshPipeline) {
  HeightField f = testing::synthetic_field();  // has a nodata texel at (50, 40)
  const shading::ProductOptions options;
  const GpuProductPipeline pipeline(Product::Svf, options);
  GpuPipelineTimings t;
  const ProductBands before = pipeline.compute(f, {}, &t);
  EXPECT_GE(t.uploaded_bytes, whole_bytes(f));  // first call: everything, and the tables
  EXPECT_TRUE(std::isnan(before.at(0, 50, 40)));

  const PixelRect edit{44, 35, 15, 9};  // covers the nodata texel, which becomes valid
  raise(f, edit);
  const ProductBands after = pipeline.compute(f, {}, &t);
  EXPECT_EQ(t.uploaded_bytes, row_bytes(f, edit));
  EXPECT_LT(t.uploaded_bytes, whole_bytes(f) / 5);
  EXPECT_FALSE(std::isnan(after.at(0, 50, 40)));

  const GpuProductPipeline fresh(Product::Svf, options);
  const ProductBands expected = fresh.compute(f);
  EXPECT_TRUE(bit_identical(after, expected));

  const ProductBands cpu = shading::compute_product(f, Product::Svf, options);
  double worst = 0.0;
  int nan_mismatches = 0;
  for (std::size_t k = 0; k < cpu.data.size(); ++k) {
    if (std::isnan(cpu.data[k]) || std::isnan(after.data[k])) {
      nan_mismatches += std::isnan(cpu.data[k]) != std::isnan(after.data[k]);
      continue;
    }
    worst = std::max(worst, std::abs(static_cast<double>(after.data[k]) - cpu.data[k]));
  }
  EXPECT_EQ(nan_mismatches, 0);
  EXPECT_LE(worst, kSvfTol);
  // The edit changed the svf near the block (it is not the old result re-served).
  EXPECT_GT(std::abs(after.at(0, 43, 39) - before.at(0, 43, 39)), 1e-3);
}

TEST_F(GpuIncrementalTest, HorizonAfterAnEditEqualsAFreshPipeline) {
  HeightField f = testing::synthetic_field();
  shading::ProductOptions options;
  options.march.azimuths = 8;
  const GpuProductPipeline pipeline(Product::Horizon, options);
  pipeline.compute(f);
  const PixelRect edit{0, 80, 100, 8};  // the southern edge rows, full width
  raise(f, edit);
  GpuPipelineTimings t;
  const ProductBands after = pipeline.compute(f, {}, &t);
  EXPECT_EQ(t.uploaded_bytes, row_bytes(f, edit));
  EXPECT_TRUE(bit_identical(after, GpuProductPipeline(Product::Horizon, options).compute(f)));
}

TEST_F(GpuIncrementalTest, UnknownChangesAreUploadedWhole) {
  HeightField f = testing::synthetic_field();
  const shading::ProductOptions options;
  const GpuProductPipeline pipeline(Product::Svf, options);
  GpuPipelineTimings t;
  pipeline.compute(f);
  // Two edits since the last compute: the first one's rectangle is forgotten.
  raise(f, {10, 10, 4, 4});
  raise(f, {60, 60, 4, 4});
  const ProductBands two_edits = pipeline.compute(f, {}, &t);
  EXPECT_EQ(t.uploaded_bytes, whole_bytes(f));  // tables and schedule kept: same size
  EXPECT_TRUE(bit_identical(two_edits, GpuProductPipeline(Product::Svf, options).compute(f)));
  // The same revision again: unchanged (every change goes through mark_dirty).
  pipeline.compute(f, {}, &t);
  EXPECT_EQ(t.uploaded_bytes, 0u);
  // Another field object, one revision on (as if edited), with other heights.
  HeightField g = testing::synthetic_field();
  g.revision = f.revision;
  pipeline.compute(g);
  HeightField h = f;
  raise(h, {0, 0, 2, 2});
  pipeline.compute(h, {}, &t);
  EXPECT_EQ(t.uploaded_bytes, whole_bytes(h));
}

// A new field built where an old one lived (same address, as allocators reuse it),
// one revision on and edited inside a rectangle: only its id tells it apart.
TEST_F(GpuIncrementalTest, ANewFieldAtAReusedAddressIsUploadedWhole) {
  const shading::ProductOptions options;
  const GpuProductPipeline pipeline(Product::Svf, options);
  std::optional<HeightField> slot(testing::synthetic_field());
  const HeightField* address = &*slot;
  pipeline.compute(*slot);
  const std::uint64_t revision = slot->revision;
  slot.emplace(testing::synthetic_field({.seed = 11}));
  ASSERT_EQ(&*slot, address);
  slot->revision = revision;
  raise(*slot, {10, 10, 4, 4});  // revision + 1, a small dirty rectangle
  GpuPipelineTimings t;
  const ProductBands got = pipeline.compute(*slot, {}, &t);
  EXPECT_EQ(t.uploaded_bytes, whole_bytes(*slot));
  EXPECT_TRUE(bit_identical(got, GpuProductPipeline(Product::Svf, options).compute(*slot)));
}

}  // namespace
}  // namespace skylit::gpu
