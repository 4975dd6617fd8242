// The terrain mesh's level of detail by screen-space error: a quadtree over the height
// field whose node at level l covers kPatchQuads · 2^l texels with one vertex every 2^l
// texels, drawn as two triangles per quad (view/terrain_draw.cpp's diagonal). Each node
// knows its geometric error: the largest vertical distance between its triangles and
// the field's heights inside it, and no less than its children's; and that of its
// triangles alone in each level-0 node's block of texels. A node is split while one
// block's error (exaggerated, plus what the triangles miss of the curvature drop), seen
// from the eye at the block's distance, exceeds the allowed pixels; nodes outside the
// view frustum are dropped by their height bounds. Smooth ground thus gets coarse
// triangles near the eye and rough ground fine ones far away; the light does not depend
// on it (texture-space shading). Neighbours of different levels meet with a skirt
// (view_terrain.vert).
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

#include "terrain/height_field.h"

namespace skylit::view {

inline constexpr int kPatchQuads = 16;  // quads along a node's side
// The geometric error allowed on screen (pixels): 2 by default (Cesium's default too);
// more draws fewer triangles, which llvmpipe's terrain pass is nearly proportional to
// (docs/viewer.md). `--mesh-error` and the window's panel take the range.
inline constexpr double kDefaultMeshErrorPx = 2.0, kMinMeshErrorPx = 0.5, kMaxMeshErrorPx = 16.0;

struct LodNode {
  int i0 = 0, j0 = 0;  // first texel
  int stride = 1;      // texels between vertices
};

struct LodView {
  glm::dmat4 view_proj{1.0};  // field frame (x east, y north, z up) to clip space
  glm::dvec3 eye{0.0};
  double pixels_per_radian = 1000.0;  // viewport height / (2 tan(fovy / 2)); 0: orthographic
  double max_error_px = kDefaultMeshErrorPx;  // geometric error allowed on screen
  double exaggeration = 1.0;
  double curvature = 0.0;             // 1 / (2 R) where the drawing drops the ground by d² / (2 R)
};

class TerrainLod {
 public:
  // Height bounds of every node (from the field's heights, nodata included as filled).
  explicit TerrainLod(const terrain::HeightField& field);
  // Bounds of the texels in `rect` recomputed after an edit.
  void update(const terrain::HeightField& field, const terrain::PixelRect& rect);

  // The nodes to draw, coarse where far. Orthographic views (pixels_per_radian 0) get
  // every node at stride 1 inside the frustum.
  std::vector<LodNode> select(const LodView& view) const;

  int levels() const { return static_cast<int>(bounds_.size()); }
  // Nodes across and down at `level` (level 0: the blocks of kPatchQuads texels).
  glm::ivec2 node_counts(int level) const {
    const Level& l = bounds_.at(static_cast<std::size_t>(level));
    return {l.nodes_x, l.nodes_y};
  }
  // Height range (min, max) of the node at `level` and node index (ni, nj).
  glm::dvec2 bounds(int level, int ni, int nj) const;
  // Its geometric error (m, unexaggerated; 0 at level 0).
  double error(int level, int ni, int nj) const;
  double spacing_x() const { return dx_; }
  double spacing_y() const { return dy_; }

 private:
  struct Level {
    int nodes_x = 0, nodes_y = 0;
    std::vector<glm::vec2> range;  // per node: min, max height
    std::vector<float> error;      // per node: geometric error (m)
    // Per level-0 node's block of texels: the largest |height − triangle| of this level's
    // triangles there (an edit recomputes the blocks near it, not whole nodes).
    std::vector<float> block_error;
  };
  void build_level0(const terrain::HeightField& field, const terrain::PixelRect& rect);
  void update_block_errors(const terrain::HeightField& field, int level, const terrain::PixelRect& rect);
  void build_parents(int ni0, int nj0, int ni1, int nj1);
  void visit(int level, int ni, int nj, const LodView& view, std::vector<LodNode>& out) const;

  int width_ = 0, height_ = 0;
  double dx_ = 1.0, dy_ = 1.0;
  std::vector<Level> bounds_;  // level 0: nodes of kPatchQuads texels (plus the shared edge)
};

}  // namespace skylit::view
