// app/shade/blocked_shade.h's plan: when a DEM goes into blocks, how large they are and
// what halo and distance they hold, against a renderer whose GPU takes squares up to a
// given side (a stand-in for the driver's limits, gpu/field_limits.h).
#include "app/shade/blocked_shade.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "shading/horizon/halo.h"
#include "shading/reference_renderer.h"

namespace {

namespace shade = skylit::app::shade;
namespace shading = skylit::shading;
using shading::Product;

// The reference renderer, with a GPU-like limit on the field's side.
class LimitedRenderer final : public shading::Renderer {
 public:
  explicit LimitedRenderer(int side) : side_(side) {}
  bool fits_field(int w, int h, Product p, const shading::ProductOptions&) override {
    return shading::traits(p).local || (w <= side_ && h <= side_);
  }
  std::string description() const override { return "limited"; }
  bool on_gpu() const override { return true; }
  void set_field(const skylit::terrain::HeightField& f) override { ref_.set_field(f); }
  void set_options(const shading::ProductOptions& o) override { ref_.set_options(o); }
  void expect_frames(int n) override { ref_.expect_frames(n); }
  void drop_horizons() override { ref_.drop_horizons(); }
  std::optional<std::string> lacks_blockers(Product p, const shading::ProductOptions& o) const override {
    return ref_.lacks_blockers(p, o);
  }
  std::optional<std::string> lacks(Product p, const shading::ProductOptions& o) const override { return ref_.lacks(p, o); }
  shading::ProductBands frame(Product p, const shading::FrameInputs& in, const shading::ProgressCallback& cb) override {
    return ref_.frame(p, in, cb);
  }
  const shading::FrameTimings& last_timings() const override { return ref_.last_timings(); }

 private:
  int side_;
  shading::ReferenceRenderer ref_;
};

skylit::terrain::DemInfo dem(int w, int h) {
  skylit::terrain::DemInfo d;
  d.width = w;
  d.height = h;
  return d;
}

TEST(BlockPlan, WholeFieldWhereItFits) {
  LimitedRenderer r(6000);
  EXPECT_FALSE(shade::plan_blocks(dem(5000, 3000), 30.0, Product::Svf, {}, std::nullopt, r));
}

TEST(BlockPlan, OverTheGpuLimitBlocksFitIt) {
  LimitedRenderer r(2000);
  const auto plan = shade::plan_blocks(dem(5000, 3000), 30.0, Product::Svf, {}, std::nullopt, r);
  ASSERT_TRUE(plan);
  EXPECT_EQ(plan->max_distance_m, skylit::horizon::kDefaultBoundedDistanceM);
  EXPECT_EQ(plan->halo, static_cast<int>(std::ceil(5000.0 / 30.0)) + skylit::horizon::kKernelMarginTexels);
  EXPECT_EQ(plan->core + 2 * plan->halo, 2000);
  for (const auto& b : plan->blocks) {
    EXPECT_LE(b.read.width, 2000);
    EXPECT_LE(b.read.height, 2000);
  }
  ASSERT_FALSE(plan->notes.empty());
  EXPECT_NE(plan->notes.front().find("GPU"), std::string::npos) << plan->notes.front();
}

TEST(BlockPlan, OverTheMemoryBudgetOnTheCpu) {
  shading::ReferenceRenderer r;
  const auto plan = shade::plan_blocks(dem(4097, 4096), 30.0, Product::Svf, {}, std::nullopt, r);
  ASSERT_TRUE(plan);
  EXPECT_EQ(plan->core + 2 * plan->halo, shade::kBlockBudgetSide);
}

TEST(BlockPlan, FineTexelsShortenTheDefaultDistance) {
  // 1 m texels: 5 km would need a 5008-texel halo; the default shrinks to a quarter block.
  LimitedRenderer r(2000);
  const auto plan = shade::plan_blocks(dem(20000, 20000), 1.0, Product::Svf, {}, std::nullopt, r);
  ASSERT_TRUE(plan);
  EXPECT_EQ(plan->max_distance_m, 2000 / 4 - skylit::horizon::kKernelMarginTexels);
  EXPECT_EQ(plan->core, 1000);
}

TEST(BlockPlan, RequestedBlocksAndTheirErrors) {
  LimitedRenderer r(2000);
  shading::ProductOptions o;
  o.march.max_distance_m = 3000;
  const auto plan = shade::plan_blocks(dem(900, 900), 30.0, Product::Shaded, o, 256, r);
  ASSERT_TRUE(plan);
  EXPECT_EQ(plan->core, 256);
  EXPECT_EQ(plan->halo, 100 + skylit::horizon::kKernelMarginTexels);
  EXPECT_EQ(plan->max_distance_m, 3000);
  EXPECT_EQ(plan->blocks.size(), 16u);
  EXPECT_THROW(shade::plan_blocks(dem(900, 900), 30.0, Product::Shaded, o, 1900, r), std::invalid_argument);
  EXPECT_THROW(shade::plan_blocks(dem(900, 900), 30.0, Product::Shaded, o, 4, r), std::invalid_argument);
  o.march.max_distance_m = 40000;  // a 1342-texel halo leaves no core in 2000
  EXPECT_THROW(shade::plan_blocks(dem(90000, 900), 30.0, Product::Shaded, o, std::nullopt, r), std::invalid_argument);
}

TEST(BlockPlan, LocalProductsNeedOneTexel) {
  LimitedRenderer r(100);  // the GPU limit does not apply to host-side products
  const auto plan = shade::plan_blocks(dem(5000, 5000), 30.0, Product::Hillshade, {}, std::nullopt, r);
  ASSERT_TRUE(plan);
  EXPECT_EQ(plan->halo, 1);
  EXPECT_EQ(plan->max_distance_m, 0.0);
  EXPECT_EQ(plan->core, shade::kBlockBudgetSide - 2);
}

}  // namespace
