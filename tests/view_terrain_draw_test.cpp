// The terrain mesh seen obliquely from above: patches of several strides meet without
// cracks, though only their joins hang skirts, and culling back faces removes no
// ground. Every pixel's ray meets the ground inside the field, so no pixel may keep the
// clear colour. llvmpipe where there is no GPU.
#include "gpu_test_util.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include <glm/matrix.hpp>

#include "gpu/gpu_renderer.h"
#include "shading/products.h"
#include "view/offscreen_target.h"
#include "view/scene_view.h"
#include "view/terrain_draw.h"
#include "view/terrain_lod.h"

namespace skylit::view {
namespace {

using TerrainDrawTest = gpu::testing::GpuTest;

// The `shaded` frame of `f` (8 azimuths), kept on the GPU by `renderer`.
gpu::GpuFrame shaded_on_gpu(gpu::GpuRenderer& renderer, const terrain::HeightField& f) {
  renderer.set_field(f);
  shading::ProductOptions o;
  o.march.azimuths = 8;
  renderer.set_options(o);
  return renderer.frame_on_gpu(shading::Product::Shaded, {});
}

// The terrain of `f`, coloured by its `shaded` frame, seen by `camera` in a size² frame
// cleared to magenta: RGB, top row first. `patches`, `skirts`: what the draw drew.
std::vector<std::uint8_t> draw_terrain(const terrain::HeightField& f, const ViewCamera& camera, int size,
                                       const TerrainStyle& style, std::size_t* patches = nullptr,
                                       std::size_t* skirts = nullptr) {
  gpu::GpuRenderer renderer;
  const gpu::GpuFrame shaded = shaded_on_gpu(renderer, f);
  TerrainDraw terrain(f);
  terrain.set_colour(shaded, style.tone);
  OffscreenTarget target(size, size);
  target.bind();
  glEnable(GL_DEPTH_TEST);
  glClearColor(1.0f, 0.0f, 1.0f, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  terrain.draw(camera.proj * camera.view, camera.eye, camera.pixels_per_radian, style);
  if (patches) *patches = terrain.last_node_count();
  if (skirts) *skirts = terrain.last_skirt_count();
  return target.read_rgb();
}

bool magenta(const std::vector<std::uint8_t>& rgb, std::size_t p) {
  return rgb[p] == 255 && rgb[p + 1] == 0 && rgb[p + 2] == 255;
}

TEST_F(TerrainDrawTest, ObliqueGroundHasNoCracksBetweenLevels) {
  gpu::testing::SyntheticFieldSpec spec;
  spec.width = spec.height = 512;
  spec.feature_size = 4000.0;
  spec.relief = 600.0;
  terrain::HeightField f = gpu::testing::synthetic_field(spec);
  f.valid[static_cast<std::size_t>(spec.nodata_j) * f.width + spec.nodata_i] = 1;  // no hole to see through
  const auto [lo, hi] = std::minmax_element(f.heights.begin(), f.heights.end());

  // The eye 150 m over the highest point, near the field's south edge, looking north 30°
  // down: with a 50° field of view the shallowest ray (a top corner) still meets the
  // lowest ground inside the field, 9 km ahead.
  const int size = 384;
  const double pitch = 30.0 * std::numbers::pi / 180.0, half_fov = std::tan(25.0 * std::numbers::pi / 180.0);
  CameraPose pose;
  pose.eye = {0.5 * (f.width - 1) * f.mean_dx(), -(f.height - 32) * f.dy, static_cast<double>(*hi) + 150.0};
  pose.forward = {0.0, std::cos(pitch), -std::sin(pitch)};
  pose.up = {0.0, std::sin(pitch), std::cos(pitch)};
  const glm::dvec3 right = glm::cross(pose.forward, pose.up);
  for (const double side : {-1.0, 1.0}) {
    const glm::dvec3 ray = pose.forward + half_fov * (pose.up + side * right);
    ASSERT_LT(ray.z, 0.0);
    const glm::dvec3 hit = pose.eye + ray * ((*lo - pose.eye.z) / ray.z);
    ASSERT_GT(hit.x, 0.0);
    ASSERT_LT(hit.x, (f.width - 1) * f.mean_dx());
    ASSERT_LT(hit.y, 0.0);
    ASSERT_GT(hit.y, -(f.height - 1) * f.dy);
  }
  const ViewCamera camera = perspective_camera(pose, f, size, size, 1.0);

  TerrainStyle style;
  style.curvature = false;
  LodView lod_view;
  lod_view.view_proj = camera.proj * camera.view;
  lod_view.eye = camera.eye;
  lod_view.pixels_per_radian = camera.pixels_per_radian;
  lod_view.max_error_px = style.max_error_px;
  std::set<int> strides;
  for (const LodNode& n : TerrainLod(f).select(lod_view)) strides.insert(n.stride);
  ASSERT_GE(strides.size(), 3u) << "patches of several strides meet in this view";

  std::size_t patches = 0, skirts = 0;
  const std::vector<std::uint8_t> rgb = draw_terrain(f, camera, size, style, &patches, &skirts);
  int empty = 0;
  for (std::size_t p = 0; p < rgb.size(); p += 3) empty += magenta(rgb, p);
  EXPECT_EQ(empty, 0) << "pixels where the ground has a crack or a culled face";
  // Skirts hang only on the sides where strides change: some, not every side's.
  EXPECT_GT(skirts, 0u);
  EXPECT_LT(skirts, 4 * patches) << patches << " patches";
}

// Straight down, every patch has stride 1 (TerrainLod): no join between strides, so no
// skirt, and every pixel is ground.
TEST_F(TerrainDrawTest, PatchesOfOneStrideHangNoSkirt) {
  gpu::testing::SyntheticFieldSpec spec;
  spec.width = spec.height = 200;
  terrain::HeightField f = gpu::testing::synthetic_field(spec);
  f.valid[static_cast<std::size_t>(spec.nodata_j) * f.width + spec.nodata_i] = 1;
  TerrainStyle style;
  std::size_t patches = 0, skirts = 1;
  const std::vector<std::uint8_t> rgb = draw_terrain(f, ortho_nadir_camera(f, 1.0), f.width, style, &patches, &skirts);
  EXPECT_EQ(patches, 13u * 13u);  // ⌈199 / 16⌉²
  EXPECT_EQ(skirts, 0u);
  int empty = 0;
  for (std::size_t p = 0; p < rgb.size(); p += 3) empty += magenta(rgb, p);
  EXPECT_EQ(empty, 0);
}

// The colour map holds display codes, so the tone curve is baked into it: the same
// frame under another tone must recolour all of it, as a fresh draw under that tone.
TEST_F(TerrainDrawTest, AnotherToneRecoloursTheSameFrame) {
  const terrain::HeightField f = gpu::testing::synthetic_field();
  gpu::GpuRenderer renderer;
  const gpu::GpuFrame shaded = shaded_on_gpu(renderer, f);
  const ViewCamera camera = ortho_nadir_camera(f, 1.0);
  OffscreenTarget target(f.width, f.height);
  target.bind();
  auto draw = [&](TerrainDraw& terrain, shading::ToneCurve tone) {
    terrain.set_colour(shaded, tone);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    TerrainStyle style;
    style.tone = tone;
    terrain.draw(camera.proj * camera.view, camera.eye, camera.pixels_per_radian, style);
    return target.read_rgb();
  };
  glEnable(GL_DEPTH_TEST);
  TerrainDraw terrain(f), fresh(f);
  const std::vector<std::uint8_t> srgb = draw(terrain, shading::ToneCurve::Srgb);
  const std::vector<std::uint8_t> linear = draw(terrain, shading::ToneCurve::Linear);
  EXPECT_NE(linear, srgb);
  EXPECT_EQ(linear, draw(fresh, shading::ToneCurve::Linear));
}

// Seen from outside, the ground ends at its edge: no skirt hangs below it (a skirt only
// hides the step to a neighbour, and there is none beyond the edge), neither at the
// field's edge nor where nodata begins (there the surface ends halfway to the first
// nodata texel, and a skirt of a join running into the hole would show through it).
// Flat ground at 0 m: a pixel whose ray meets z = 0 outside the valid ground sees
// nothing (before that the ray is above the ground, after it below), one whose ray
// meets it inside sees ground.
TEST_F(TerrainDrawTest, NoSkirtHangsBelowTheGroundsEdge) {
  for (const int hole_rows : {0, 100}) {  // nodata across the south of the field
    terrain::HeightField f(512, 512, 30.0);
    for (int j = f.height - hole_rows; j < f.height; ++j)
      for (int i = 0; i < f.width; ++i) f.valid[static_cast<std::size_t>(j) * f.width + i] = 0;
    const double dx = f.mean_dx(), dy = f.dy;
    const double south = f.height - hole_rows - 0.5;  // the ground's south edge (texel rows)
    const int size = 256;
    CameraPose pose;  // 12 km south of the field's south edge, 9 km up, looking north 30° down
    const double pitch = 30.0 * std::numbers::pi / 180.0;
    pose.eye = {0.5 * (f.width - 1) * dx, -(f.height - 0.5) * dy - 12000.0, 9000.0};
    pose.forward = {0.0, std::cos(pitch), -std::sin(pitch)};
    pose.up = {0.0, std::sin(pitch), std::cos(pitch)};
    const ViewCamera camera = perspective_camera(pose, f, size, size, 1.0);

    TerrainStyle style;
    style.curvature = false;
    const std::vector<std::uint8_t> rgb = draw_terrain(f, camera, size, style);

    const glm::dmat4 inverse = glm::inverse(camera.proj * camera.view);
    int outside = 0, outside_drawn = 0, inside = 0, inside_empty = 0;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const double nx = (x + 0.5) / size * 2.0 - 1.0, ny = 1.0 - (y + 0.5) / size * 2.0;  // top row first
        const glm::dvec4 far = inverse * glm::dvec4(nx, ny, 1.0, 1.0);
        const glm::dvec3 ray = glm::dvec3(far) / far.w - pose.eye;
        if (ray.z >= 0.0) continue;
        const glm::dvec3 hit = pose.eye + ray * (-pose.eye.z / ray.z);
        // Texel coordinates of the hit; the ground spans [−0.5, width − 0.5] × [−0.5, south].
        const double i = hit.x / dx, j = -hit.y / dy;
        const double margin = std::min({i + 0.5, f.width - 0.5 - i, j + 0.5, south - j});
        const std::size_t p = (static_cast<std::size_t>(y) * size + x) * 3;
        const bool empty = magenta(rgb, p);
        if (margin < -1.0) {
          ++outside;
          outside_drawn += !empty;
        } else if (margin > 1.0) {
          ++inside;
          inside_empty += empty;
        }
      }
    ASSERT_GT(outside, 1000) << "the view sees the ground in front of the field; hole " << hole_rows;
    ASSERT_GT(inside, 1000) << hole_rows;
    EXPECT_EQ(outside_drawn, 0) << "pixels drawn below the ground's edge; hole " << hole_rows;
    EXPECT_EQ(inside_empty, 0) << hole_rows;
  }
}

}  // namespace
}  // namespace skylit::view
