// The terrain mesh's level of detail (view/terrain_lod.h), checked by brute force: every
// texel of every selected node lies within the allowed pixels of the node's triangles as
// seen from the eye; a node's error is no less than its children's; a plane is drawn
// by its coarsest nodes exactly; an edit's update gives the errors of a fresh build.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "terrain/editing.h"
#include "terrain/synthetic.h"
#include "view/scene_view.h"
#include "view/terrain_lod.h"

namespace skylit::view {
namespace {

terrain::HeightField rough_field() {
  terrain::SyntheticOptions o;
  o.width = 520;
  o.height = 480;
  o.spacing = 30.0;
  o.seed = 11;
  o.relief = 600.0;
  return terrain::make_synthetic_terrain(o);
}

// Height of the drawn triangles of stride s at texel (i, j) of the node at (i0, j0):
// quads between vertices s apart (the last clamped to the field's edge), split along the
// (1, 0)–(0, 1) diagonal as view/terrain_draw.cpp's indices do.
double mesh_height(const terrain::HeightField& f, int i0, int j0, int s, int i, int j) {
  const int x0 = i0 + (i - i0) / s * s, y0 = j0 + (j - j0) / s * s;
  const int x1 = std::min(x0 + s, f.width - 1), y1 = std::min(y0 + s, f.height - 1);
  if (x1 == x0 || y1 == y0) return f.at(i, j);  // on the field's last row or column
  const double u = static_cast<double>(i - x0) / (x1 - x0), v = static_cast<double>(j - y0) / (y1 - y0);
  const double h00 = f.at(x0, y0), h10 = f.at(x1, y0), h01 = f.at(x0, y1), h11 = f.at(x1, y1);
  return u + v <= 1.0 ? h00 + u * (h10 - h00) + v * (h01 - h00) : h11 + (1 - u) * (h01 - h11) + (1 - v) * (h10 - h11);
}

LodView low_view(const terrain::HeightField& f, double exaggeration) {
  const double x = 0.3 * f.width * f.mean_dx(), y = -0.8 * f.height * f.dy;
  const double ground = ground_of(f, exaggeration)(x, y);
  CameraPose pose;
  pose.eye = {x, y, ground + 150.0};
  pose.forward = glm::normalize(glm::dvec3(0.3, 1.0, -0.08));
  pose.up = glm::normalize(glm::cross(glm::cross(pose.forward, glm::dvec3(0, 0, 1)), pose.forward));
  const ViewCamera c = perspective_camera(pose, f, 1280, 720, exaggeration);
  LodView v;
  v.view_proj = c.proj * c.view;
  v.eye = c.eye;
  v.pixels_per_radian = c.pixels_per_radian;
  v.exaggeration = exaggeration;
  return v;
}

TEST(TerrainLod, EveryTexelOfTheSelectedNodesIsWithinTheAllowedPixels) {
  const terrain::HeightField f = rough_field();
  const TerrainLod lod(f);
  for (double exaggeration : {1.0, 3.0}) {
    const LodView v = low_view(f, exaggeration);
    const std::vector<LodNode> nodes = lod.select(v);
    ASSERT_FALSE(nodes.empty());
    double worst_px = 0.0;
    int coarse = 0;
    for (const LodNode& n : nodes) {
      coarse += n.stride > 1;
      const int span = kPatchQuads * n.stride;
      for (int j = n.j0; j <= std::min(f.height - 1, n.j0 + span); ++j)
        for (int i = n.i0; i <= std::min(f.width - 1, n.i0 + span); ++i) {
          const glm::dvec3 p(i * f.mean_dx(), -j * f.dy, f.at(i, j) * exaggeration);
          const double miss = std::abs(f.at(i, j) - mesh_height(f, n.i0, n.j0, n.stride, i, j)) * exaggeration;
          worst_px = std::max(worst_px, miss / glm::length(p - v.eye) * v.pixels_per_radian);
        }
    }
    std::printf("exaggeration %.0f: %zu nodes, %d coarse, worst %.2f px\n", exaggeration, nodes.size(), coarse, worst_px);
    EXPECT_LE(worst_px, v.max_error_px) << exaggeration;
    EXPECT_GT(coarse, 0) << "far nodes are coarse";
    EXPECT_GT(worst_px, 0.2 * v.max_error_px) << "and no finer than they need";
  }
}

TEST(TerrainLod, ANodesErrorIsNoLessThanItsChildrensAndAPlaneIsExact) {
  const terrain::HeightField f = rough_field();
  const TerrainLod lod(f);
  for (int l = 1; l < lod.levels(); ++l) {
    const int nx = (f.width - 2) / (kPatchQuads << l) + 1, ny = (f.height - 2) / (kPatchQuads << l) + 1;
    for (int nj = 0; nj < ny; ++nj)
      for (int ni = 0; ni < nx; ++ni) {
        EXPECT_GT(lod.error(l, ni, nj), 0.0);
        for (int c = 0; c < 4; ++c) {
          const int ci = 2 * ni + (c & 1), cj = 2 * nj + (c >> 1);
          if (ci * (kPatchQuads << (l - 1)) >= f.width - 1 || cj * (kPatchQuads << (l - 1)) >= f.height - 1) continue;
          EXPECT_GE(lod.error(l, ni, nj), lod.error(l - 1, ci, cj)) << l << " " << ni << " " << nj;
        }
      }
  }
  terrain::HeightField plane = f;
  for (int j = 0; j < plane.height; ++j)
    for (int i = 0; i < plane.width; ++i) plane.heights[static_cast<std::size_t>(j) * plane.width + i] = 500.0f + 0.2f * i - 0.1f * j;
  const TerrainLod flat(plane);
  EXPECT_LT(flat.error(flat.levels() - 1, 0, 0), 1e-3);
  for (const LodNode& n : flat.select(low_view(plane, 1.0))) EXPECT_EQ(n.stride, 1 << (flat.levels() - 1));
}

TEST(TerrainLod, AnEditsUpdateGivesTheErrorsOfAFreshBuild) {
  terrain::HeightField f = rough_field();
  TerrainLod lod(f);
  const terrain::PixelRect r{140, 90, 25, 30};
  std::vector<float> v;
  for (int j = r.y0; j < r.y1(); ++j)
    for (int i = r.x0; i < r.x1(); ++i) v.push_back(f.at(i, j) + 80.0f * std::sin(0.3f * i) * std::cos(0.2f * j));
  terrain::replace_heights(f, r, v);
  lod.update(f, r);
  const TerrainLod fresh(f);
  for (int l = 0; l < lod.levels(); ++l) {
    const int nx = (f.width - 2) / (kPatchQuads << l) + 1, ny = (f.height - 2) / (kPatchQuads << l) + 1;
    for (int nj = 0; nj < ny; ++nj)
      for (int ni = 0; ni < nx; ++ni) {
        EXPECT_EQ(lod.error(l, ni, nj), fresh.error(l, ni, nj)) << l << " " << ni << " " << nj;
        EXPECT_EQ(lod.bounds(l, ni, nj), fresh.bounds(l, ni, nj));
      }
  }
}

}  // namespace
}  // namespace skylit::view
