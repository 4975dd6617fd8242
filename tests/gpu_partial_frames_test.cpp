// Partial frames (GpuProductPipeline::set_partial_frames): a frame left on the GPU under
// the last frame's lighting, on the same field revision, shades again only the texels
// the spheres reach, the last frame's and this one's. Checked bit for bit against a
// pipeline that shades every texel of every frame (itself matched to the CPU reference
// by gpu_blockers_test and gpu_frame_reuse_test), and the texels it says it left must
// be the last frame's.
#include "gpu_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "gpu/gpu_pipeline.h"
#include "shading/lighting.h"
#include "terrain/editing.h"
#include "terrain/synthetic.h"

namespace skylit::gpu {
namespace {

using shading::Product;
using shading::ProductOptions;

using GpuPartialFramesTest = testing::GpuTest;

using testing::sun_at;

using testing::balloon_over;
using testing::hills;

bool same_bits(float a, float b) { return a == b || (std::isnan(a) && std::isnan(b)); }

std::size_t differing(const std::vector<float>& a, const std::vector<float>& b) {
  std::size_t n = 0;
  for (std::size_t k = 0; k < a.size(); ++k) n += same_bits(a[k], b[k]) ? 0 : 1;
  return n;
}

struct Frames {
  GpuProductPipeline partial, whole;  // with partial frames, and shading every texel
  GpuPipelineTimings timings;
  std::vector<float> last;  // the partial pipeline's last frame
  explicit Frames(const ProductOptions& o) : partial(Product::Shaded, o, true), whole(Product::Shaded, o, true) {
    for (GpuProductPipeline* p : {&partial, &whole}) {
      p->keep_visibility(true);
      p->keep_sky_irradiance(true);
    }
    whole.set_partial_frames(false);
  }
  // Both pipelines' frame, compared bit for bit; the partial one's texels outside what it
  // says it changed compared with its last frame. Returns the frame.
  std::vector<float> frame(const terrain::HeightField& f, const shading::Lighting& l,
                           const std::vector<blockers::Sphere>& spheres) {
    for (GpuProductPipeline* p : {&partial, &whole}) {
      p->set_lighting(l);
      p->set_spheres(spheres);
    }
    const std::vector<float> expected = whole.compute_on_gpu(f).download_all<float>();
    std::vector<float> got = partial.compute_on_gpu(f, {}, &timings).download_all<float>();
    EXPECT_EQ(differing(got, expected), 0u) << "a partial frame equals the whole one";
    if (timings.shading_kept) {
      EXPECT_TRUE(partial.last_changed().has_value());
      std::vector<char> inside(got.size() / 3, 0);  // Shaded: 3 bands, R, G, B
      for (const terrain::PixelRect& r : *partial.last_changed())
        for (int j = r.y0; j < r.y1(); ++j)
          for (int i = r.x0; i < r.x1(); ++i) inside[static_cast<std::size_t>(j) * f.width + i] = 1;
      std::size_t outside_changed = 0;
      for (std::size_t k = 0; k < got.size(); ++k)
        if (!inside[k % inside.size()] && !same_bits(got[k], last[k])) ++outside_changed;
      EXPECT_EQ(outside_changed, 0u) << "the texels it left are the last frame's";
    } else {
      EXPECT_FALSE(partial.last_changed().has_value());
    }
    last = got;
    return got;
  }
};

TEST_F(GpuPartialFramesTest, AFrameUnderTheSameLightingEqualsAWholeOneAndChangesOnlyWhatTheSpheresReach) {
  terrain::HeightField f = hills();
  ProductOptions o;
  o.lighting = sun_at(140.0, 30.0, "preetham");
  o.lighting->colour = true;
  Frames frames(o);
  const auto here = balloon_over(f, 60, 50), there = balloon_over(f, 190, 150);

  // The visibility, then the sky kept: whole frames.
  frames.frame(f, *o.lighting, here);
  EXPECT_FALSE(frames.timings.shading_kept);
  const std::vector<float> at_here = frames.frame(f, *o.lighting, here);
  EXPECT_FALSE(frames.timings.shading_kept);

  // The same lighting: partial. The balloon flown far: its shadows leave and arrive.
  frames.frame(f, *o.lighting, here);
  EXPECT_TRUE(frames.timings.shading_kept);
  const std::vector<float> at_there = frames.frame(f, *o.lighting, there);
  EXPECT_TRUE(frames.timings.shading_kept);
  EXPECT_GT(differing(at_here, at_there), 1000u) << "the balloon's shadows moved";
  const std::vector<float> open = frames.frame(f, *o.lighting, {});
  EXPECT_TRUE(frames.timings.shading_kept) << "no sphere: the same blocked pipeline, every texel left";
  EXPECT_GT(differing(open, at_there), 1000u);
  frames.frame(f, *o.lighting, here);
  EXPECT_TRUE(frames.timings.shading_kept);

  // The sun moved (the same sky model): whole, then partial again.
  shading::Lighting moved = *o.lighting;
  moved.sun = sun_at(140.04, 30.02, "preetham").sun;
  frames.frame(f, moved, there);
  EXPECT_FALSE(frames.timings.shading_kept);
  frames.frame(f, moved, here);
  EXPECT_TRUE(frames.timings.shading_kept);

  // An edit: the visibility again, then the sky kept, then partial.
  {
    const terrain::PixelRect r{100, 80, 6, 6};
    std::vector<float> v;
    for (int j = r.y0; j < r.y1(); ++j)
      for (int i = r.x0; i < r.x1(); ++i) v.push_back(f.at(i, j) + 30.0f);
    terrain::replace_heights(f, r, v);
  }
  frames.frame(f, moved, here);
  EXPECT_FALSE(frames.timings.shading_kept);
  frames.frame(f, moved, there);
  EXPECT_FALSE(frames.timings.shading_kept);
  frames.frame(f, moved, here);
  EXPECT_TRUE(frames.timings.shading_kept);

  // Off: every frame whole.
  frames.partial.set_partial_frames(false);
  frames.frame(f, moved, there);
  EXPECT_FALSE(frames.timings.shading_kept);
}

}  // namespace
}  // namespace skylit::gpu
