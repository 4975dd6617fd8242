// The incremental refresh of the kept visibility after an edit (gpu/visibility_refresh.h,
// GpuProductPipeline::set_refresh_budget). Checked against a whole recompute, the
// independent path (itself matched to the CPU reference by gpu_products_test):
//  * the region plan: the edit's grown rectangle, then rings that add at least the
//    budget, never overlap, and end holding the field;
//  * on the GPU (llvmpipe without one), swept and marched pipelines, unblocked and with
//    sphere blockers: the edit's frame equals a fresh marching pipeline on the edited
//    field bit for bit inside the refreshed rectangle, and the frame before the edit
//    outside it (except where the sun's shadow, recomputed whole every frame, moved); the
//    later frames converge, and the last equals the fresh pipeline everywhere. The edit
//    changes texels outside the first rectangle, so the refinement is needed.
#include "gpu_test_util.h"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "gpu/gpu_pipeline.h"
#include "gpu/gpu_renderer.h"
#include "gpu/visibility_refresh.h"
#include "shading/lighting.h"
#include "terrain/editing.h"

namespace skylit::gpu {
namespace {

using shading::Product;
using shading::ProductBands;
using shading::ProductOptions;
using terrain::PixelRect;

bool inside(const PixelRect& r, int i, int j) { return i >= r.x0 && i < r.x1() && j >= r.y0 && j < r.y1(); }

TEST(VisibilityRefresh, GrowsFromTheEditByRingsUntilItHoldsTheField) {
  VisibilityRefresh plan;
  plan.reset(100, 60);
  EXPECT_TRUE(plan.complete());
  EXPECT_TRUE(plan.refine(10).empty());
  const PixelRect first = plan.edit({90, 5, 6, 4}, 8);
  EXPECT_EQ(first, (PixelRect{82, 0, 18, 17}));  // clipped at the north and east edges
  EXPECT_EQ(plan.stale_texels(), 100u * 60u - 18u * 17u);
  std::vector<int> covered(100 * 60, 0);
  for (int j = first.y0; j < first.y1(); ++j)
    for (int i = first.x0; i < first.x1(); ++i) ++covered[j * 100 + i];
  int steps = 0;
  while (!plan.complete()) {
    const std::size_t stale = plan.stale_texels();
    const std::vector<PixelRect> added = plan.refine(500);
    ASSERT_FALSE(added.empty());
    ASSERT_LE(added.size(), 4u);
    std::size_t area = 0;
    for (const PixelRect& r : added) {
      area += static_cast<std::size_t>(r.width) * r.height;
      for (int j = r.y0; j < r.y1(); ++j)
        for (int i = r.x0; i < r.x1(); ++i) ++covered[j * 100 + i];
    }
    EXPECT_EQ(stale - plan.stale_texels(), area);
    EXPECT_TRUE(area >= 500 || plan.complete()) << area;
    ++steps;
  }
  for (int c : covered) ASSERT_EQ(c, 1);  // every texel exactly once
  EXPECT_EQ(plan.current(), (PixelRect{0, 0, 100, 60}));
  EXPECT_GE(steps, 5);
  EXPECT_LE(steps, 12);
  EXPECT_THROW(plan.edit({}, 8), std::invalid_argument);
  EXPECT_THROW(plan.edit({200, 200, 4, 4}, 8), std::invalid_argument);
}

using GpuVisibilityRefreshTest = testing::GpuTest;

using testing::sun_at;

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// A raised disc-like block: + 400 m over `r`, through the editing API (one revision).
void raise(terrain::HeightField& f, const PixelRect& r) {
  std::vector<float> v;
  for (int j = r.y0; j < r.y1(); ++j)
    for (int i = r.x0; i < r.x1(); ++i) v.push_back(f.at(i, j) + 400.0f);
  terrain::replace_heights(f, r, v);
}

void check_refresh(horizon::HorizonMethod method, Product product, bool blocked) {
  terrain::HeightField f = testing::synthetic_field();
  ProductOptions o;
  o.march.azimuths = 8;
  o.march.method = method;
  GpuRenderer r;
  r.set_field(f);
  r.set_options(o);
  r.expect_frames(10);
  const std::size_t texels = f.size(), budget = texels / 5;
  r.set_refresh_budget(budget);
  shading::FrameInputs in{sun_at(135, 30, "preetham"), {}, std::nullopt};
  if (blocked) in.spheres = {{{40.0 * f.mean_dx(), -30.0 * f.dy, f.at(40, 30) + 80.0}, 60.0}};
  const ProductBands before = r.frame(product, in);
  EXPECT_EQ(r.last_timings().refreshed_texels, texels);
  // The sun's shadow is recomputed whole every frame: where the raised block moves it,
  // texels outside the refreshed rectangle change at once.
  const ProductBands shadow_before = r.frame(Product::Shadow, in);

  const PixelRect edit{60, 50, 8, 6};
  raise(f, edit);
  const ProductBands shadow_after = r.frame(Product::Shadow, in);
  const ProductBands first = r.frame(product, in);
  const PixelRect grown{edit.x0 - 8, edit.y0 - 8, edit.width + 16, edit.height + 16};
  EXPECT_EQ(r.last_timings().refreshed_texels, static_cast<std::size_t>(grown.width) * grown.height);
  EXPECT_EQ(r.last_timings().stale_texels, texels - static_cast<std::size_t>(grown.width) * grown.height);
  EXPECT_FALSE(r.last_timings().horizons_reused);

  r.context().make_current();
  ProductOptions lit = o;
  lit.lighting = in.lighting;
  lit.march.method = horizon::HorizonMethod::March;  // refreshed texels are marched
  GpuProductPipeline whole(product, lit, blocked);
  if (blocked) whole.set_spheres(in.spheres);
  const ProductBands expected = whole.compute(f);
  ASSERT_EQ(expected.data.size(), first.data.size());
  // A swept pipeline sweeps the sun too, every frame: compared where the suns agree.
  GpuProductPipeline whole_sun(Product::Shadow, lit, blocked);
  if (blocked) whole_sun.set_spheres(in.spheres);
  const ProductBands sun_expected = whole_sun.compute(f);
  std::vector<char> same_sun(texels);
  std::size_t sun_agrees = 0;
  for (int j = 0; j < f.height; ++j)
    for (int i = 0; i < f.width; ++i) {
      same_sun[j * f.width + i] = same_bits(shadow_after.at(0, i, j), sun_expected.at(0, i, j));
      sun_agrees += same_sun[j * f.width + i];
    }
  if (method == horizon::HorizonMethod::March) {
    EXPECT_EQ(sun_agrees, texels);
  }
  EXPECT_GT(sun_agrees, texels * 9 / 10);
  int wrong_inside = 0, wrong_outside = 0, stale_differs = 0;
  for (int b = 0; b < first.bands; ++b)
    for (int j = 0; j < f.height; ++j)
      for (int i = 0; i < f.width; ++i) {
        const float got = first.at(b, i, j);
        if (inside(grown, i, j)) {
          wrong_inside += same_sun[j * f.width + i] && !same_bits(got, expected.at(b, i, j));
        } else if (same_bits(shadow_before.at(0, i, j), shadow_after.at(0, i, j))) {
          wrong_outside += !same_bits(got, before.at(b, i, j));
          stale_differs += !same_bits(got, expected.at(b, i, j));
        }
      }
  EXPECT_EQ(wrong_inside, 0);
  EXPECT_EQ(wrong_outside, 0);
  EXPECT_GT(stale_differs, 0);  // the raised block is seen from outside the rectangle

  ProductBands last = first;
  int frames = 0;
  // Irradiance (no tone map on the host) refines with the bands left on the GPU, as the
  // viewer does: its row-by-row copies of the refreshed columns are checked too.
  const bool on_gpu = product == Product::Irradiance;
  for (std::size_t stale = r.last_timings().stale_texels; stale > 0 && frames < 20; stale = r.last_timings().stale_texels) {
    if (on_gpu) {
      const GpuFrame g = r.frame_on_gpu(product, in);
      last.data = g.bands.download_all<float>();
    } else {
      last = r.frame(product, in);
    }
    EXPECT_GE(r.last_timings().refreshed_texels, std::min(budget, stale));
    EXPECT_EQ(r.last_timings().stale_texels, stale - r.last_timings().refreshed_texels);
    if (!blocked) {
      EXPECT_EQ(r.last_timings().uploaded_bytes, 0u);  // resident already (spheres upload per frame)
    }
    ++frames;
  }
  EXPECT_LE(frames, 5);  // texels / budget frames at most
  EXPECT_EQ(r.last_timings().stale_texels, 0u);
  int wrong_last = 0;
  for (int b = 0; b < last.bands; ++b)
    for (int j = 0; j < f.height; ++j)
      for (int i = 0; i < f.width; ++i)
        wrong_last += same_sun[j * f.width + i] && !same_bits(last.at(b, i, j), expected.at(b, i, j));
  EXPECT_EQ(wrong_last, 0);
  // Then the kept visibility is reused as before.
  r.frame(product, in);
  EXPECT_TRUE(r.last_timings().horizons_reused);
  EXPECT_EQ(r.last_timings().refreshed_texels, 0u);
}

TEST_F(GpuVisibilityRefreshTest, SweptIrradianceConvergesToAWholeRecompute) {
  check_refresh(horizon::HorizonMethod::Sweep, Product::Irradiance, false);
}

TEST_F(GpuVisibilityRefreshTest, MarchedShadedConvergesToAWholeRecompute) {
  check_refresh(horizon::HorizonMethod::March, Product::Shaded, false);
}

TEST_F(GpuVisibilityRefreshTest, BlockedFramesConvergeToAWholeRecompute) {
  check_refresh(horizon::HorizonMethod::Sweep, Product::Shaded, true);
  check_refresh(horizon::HorizonMethod::March, Product::Irradiance, true);
}

// Without a budget the edit's frame recomputes everything, as before; two edits
// between frames too (the first one's rectangle is not known).
TEST_F(GpuVisibilityRefreshTest, NoBudgetOrTwoEditsRecomputeTheWholeField) {
  terrain::HeightField f = testing::synthetic_field();
  ProductOptions o;
  o.march.azimuths = 8;
  GpuRenderer r;
  r.set_field(f);
  r.set_options(o);
  r.expect_frames(10);
  const shading::FrameInputs in{sun_at(200, 40, "preetham"), {}, std::nullopt};
  r.frame(Product::Irradiance, in);
  raise(f, {10, 10, 4, 4});
  r.frame(Product::Irradiance, in);
  EXPECT_EQ(r.last_timings().refreshed_texels, f.size());
  r.set_refresh_budget(100);
  raise(f, {10, 10, 4, 4});
  raise(f, {60, 60, 4, 4});
  r.frame(Product::Irradiance, in);
  EXPECT_EQ(r.last_timings().refreshed_texels, f.size());
  EXPECT_EQ(r.last_timings().stale_texels, 0u);
}

}  // namespace
}  // namespace skylit::gpu
