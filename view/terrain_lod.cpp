#include "view/terrain_lod.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace skylit::view {
namespace {

int nodes_for(int texels, int span) { return std::max(1, (texels - 1 + span - 1) / span); }

}  // namespace

TerrainLod::TerrainLod(const terrain::HeightField& field)
    : width_(field.width), height_(field.height), dx_(field.mean_dx()), dy_(field.dy) {
  int span = kPatchQuads;
  do {
    Level level;
    level.nodes_x = nodes_for(width_, span);
    level.nodes_y = nodes_for(height_, span);
    level.range.assign(static_cast<std::size_t>(level.nodes_x) * level.nodes_y, glm::vec2(0.0f));
    level.error.assign(level.range.size(), 0.0f);
    level.block_error.assign(bounds_.empty() ? level.range.size() : bounds_[0].range.size(), 0.0f);
    bounds_.push_back(std::move(level));
    span *= 2;
  } while (bounds_.back().nodes_x > 1 || bounds_.back().nodes_y > 1);
  update(field, field.bounds());
}

void TerrainLod::update(const terrain::HeightField& field, const terrain::PixelRect& rect) {
  if (rect.empty()) return;
  build_level0(field, rect);
  const int ni0 = std::max(0, (rect.x0 - 1) / kPatchQuads), nj0 = std::max(0, (rect.y0 - 1) / kPatchQuads);
  const int ni1 = std::min(bounds_[0].nodes_x - 1, rect.x1() / kPatchQuads);
  const int nj1 = std::min(bounds_[0].nodes_y - 1, rect.y1() / kPatchQuads);
  for (int l = 1; l < levels(); ++l) update_block_errors(field, l, rect);
  build_parents(ni0, nj0, ni1, nj1);
}

void TerrainLod::update_block_errors(const terrain::HeightField& field, int level, const terrain::PixelRect& rect) {
  const int s = 1 << level;
  std::vector<float>& errors = bounds_[static_cast<std::size_t>(level)].block_error;
  const int nx = bounds_[0].nodes_x, ny = bounds_[0].nodes_y;
  // An edited texel moves the triangles of the quads it is a corner of: s texels around.
  const int bi0 = std::max(0, (rect.x0 - s - 1) / kPatchQuads), bj0 = std::max(0, (rect.y0 - s - 1) / kPatchQuads);
  const int bi1 = std::min(nx - 1, (rect.x1() + s) / kPatchQuads), bj1 = std::min(ny - 1, (rect.y1() + s) / kPatchQuads);
  for (int bj = bj0; bj <= bj1; ++bj)
    for (int bi = bi0; bi <= bi1; ++bi) {
      float worst = 0.0f;
      for (int j = bj * kPatchQuads; j <= std::min(height_ - 1, (bj + 1) * kPatchQuads); ++j) {
        // The quad holding texel (i, j): vertices every s texels from 0, the last clamped
        // to the field's edge (as view_terrain.vert places them); its triangles (00, 10,
        // 01) and (10, 11, 01).
        const int y0 = std::min(j / s * s, std::max(height_ - 2, 0)), y1 = std::min(y0 + s, height_ - 1);
        for (int i = bi * kPatchQuads; i <= std::min(width_ - 1, (bi + 1) * kPatchQuads); ++i) {
          const int x0 = std::min(i / s * s, std::max(width_ - 2, 0)), x1 = std::min(x0 + s, width_ - 1);
          if (x1 == x0 || y1 == y0) continue;
          const float u = static_cast<float>(i - x0) / static_cast<float>(x1 - x0);
          const float v = static_cast<float>(j - y0) / static_cast<float>(y1 - y0);
          const float h00 = field.at(x0, y0), h10 = field.at(x1, y0), h01 = field.at(x0, y1), h11 = field.at(x1, y1);
          const float mesh = u + v <= 1.0f ? h00 + u * (h10 - h00) + v * (h01 - h00)
                                           : h11 + (1.0f - u) * (h01 - h11) + (1.0f - v) * (h10 - h11);
          const float e = std::abs(field.at(i, j) - mesh);
          if (e > worst) worst = e;  // NaN (nodata) never counts
        }
      }
      errors[static_cast<std::size_t>(bj) * nx + bi] = worst;
    }
}

void TerrainLod::build_level0(const terrain::HeightField& field, const terrain::PixelRect& rect) {
  Level& level = bounds_[0];
  // A node covers texels [n·P, n·P + P] (its far edge is shared with the next node).
  const int ni0 = std::max(0, (rect.x0 - 1) / kPatchQuads), nj0 = std::max(0, (rect.y0 - 1) / kPatchQuads);
  const int ni1 = std::min(level.nodes_x - 1, rect.x1() / kPatchQuads);
  const int nj1 = std::min(level.nodes_y - 1, rect.y1() / kPatchQuads);
  for (int nj = nj0; nj <= nj1; ++nj)
    for (int ni = ni0; ni <= ni1; ++ni) {
      float lo = std::numeric_limits<float>::max(), hi = std::numeric_limits<float>::lowest();
      for (int j = nj * kPatchQuads; j <= std::min(height_ - 1, (nj + 1) * kPatchQuads); ++j)
        for (int i = ni * kPatchQuads; i <= std::min(width_ - 1, (ni + 1) * kPatchQuads); ++i) {
          lo = std::min(lo, field.at(i, j));
          hi = std::max(hi, field.at(i, j));
        }
      level.range[static_cast<std::size_t>(nj) * level.nodes_x + ni] = {lo, hi};
    }
}

void TerrainLod::build_parents(int ni0, int nj0, int ni1, int nj1) {
  for (std::size_t l = 1; l < bounds_.size(); ++l) {
    ni0 /= 2, nj0 /= 2, ni1 /= 2, nj1 /= 2;
    const Level& child = bounds_[l - 1];
    Level& level = bounds_[l];
    for (int nj = nj0; nj <= std::min(nj1, level.nodes_y - 1); ++nj)
      for (int ni = ni0; ni <= std::min(ni1, level.nodes_x - 1); ++ni) {
        glm::vec2 r(std::numeric_limits<float>::max(), std::numeric_limits<float>::lowest());
        float e = 0.0f;  // the blocks' of this level, then the children's
        const int per = 1 << l;
        for (int bj = nj * per; bj < std::min((nj + 1) * per, bounds_[0].nodes_y); ++bj)
          for (int bi = ni * per; bi < std::min((ni + 1) * per, bounds_[0].nodes_x); ++bi)
            e = std::max(e, level.block_error[static_cast<std::size_t>(bj) * bounds_[0].nodes_x + bi]);
        for (int cj = 2 * nj; cj <= std::min(2 * nj + 1, child.nodes_y - 1); ++cj)
          for (int ci = 2 * ni; ci <= std::min(2 * ni + 1, child.nodes_x - 1); ++ci) {
            const std::size_t c = static_cast<std::size_t>(cj) * child.nodes_x + ci;
            r = {std::min(r.x, child.range[c].x), std::max(r.y, child.range[c].y)};
            e = std::max(e, child.error[c]);
          }
        level.range[static_cast<std::size_t>(nj) * level.nodes_x + ni] = r;
        level.error[static_cast<std::size_t>(nj) * level.nodes_x + ni] = e;
      }
  }
}

double TerrainLod::error(int level, int ni, int nj) const {
  const Level& l = bounds_.at(static_cast<std::size_t>(level));
  return l.error.at(static_cast<std::size_t>(nj) * l.nodes_x + ni);
}

glm::dvec2 TerrainLod::bounds(int level, int ni, int nj) const {
  const Level& l = bounds_.at(static_cast<std::size_t>(level));
  return glm::dvec2(l.range.at(static_cast<std::size_t>(nj) * l.nodes_x + ni));
}

std::vector<LodNode> TerrainLod::select(const LodView& view) const {
  std::vector<LodNode> out;
  const int top = levels() - 1;
  visit(top, 0, 0, view, out);
  return out;
}

void TerrainLod::visit(int level, int ni, int nj, const LodView& view, std::vector<LodNode>& out) const {
  const Level& l = bounds_[static_cast<std::size_t>(level)];
  if (ni >= l.nodes_x || nj >= l.nodes_y) return;
  const int stride = 1 << level, span = kPatchQuads * stride;
  const int i0 = ni * span, j0 = nj * span;
  const int i1 = std::min(width_ - 1, i0 + span), j1 = std::min(height_ - 1, j0 + span);
  const glm::vec2 r = l.range[static_cast<std::size_t>(nj) * l.nodes_x + ni];
  const glm::dvec3 lo(i0 * dx_, -j1 * dy_, r.x * view.exaggeration), hi(i1 * dx_, -j0 * dy_, r.y * view.exaggeration);

  // Frustum cull: the box is out when all 8 corners lie beyond one clip plane.
  std::array<glm::dvec4, 8> clip;
  for (int c = 0; c < 8; ++c)
    clip[c] = view.view_proj * glm::dvec4(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z, 1.0);
  for (int axis = 0; axis < 3; ++axis)
    for (int sign : {-1, 1}) {
      bool all_out = true;
      for (const glm::dvec4& p : clip) all_out = all_out && sign * p[axis] > p.w;
      if (all_out) return;
    }

  bool split = level > 0;
  if (split && view.pixels_per_radian > 0.0) {
    // A quadratic a·x² is missed by at most a·h²/4 by its chords of length h; a
    // triangle's longest side is the quad's diagonal.
    const double side = stride * std::max(dx_, dy_);
    const double curve = view.curvature * 2.0 * side * side / 4.0;
    // The node's triangles' error block by block (a level-0 node's texels each), each
    // seen from the block's own nearest point: the far blocks of a node near the eye
    // need not be as fine as its nearest. Split as soon as one block shows too much.
    const Level& blocks = bounds_[0];
    auto shows_too_much = [&] {
      for (int bj = nj * stride; bj < std::min((nj + 1) * stride, blocks.nodes_y); ++bj)
        for (int bi = ni * stride; bi < std::min((ni + 1) * stride, blocks.nodes_x); ++bi) {
          const double error =
              l.block_error[static_cast<std::size_t>(bj) * blocks.nodes_x + bi] * view.exaggeration + curve;
          const glm::dvec3 block_lo(bi * kPatchQuads * dx_, -std::min(height_ - 1, (bj + 1) * kPatchQuads) * dy_, lo.z);
          const glm::dvec3 block_hi(std::min(width_ - 1, (bi + 1) * kPatchQuads) * dx_, -bj * kPatchQuads * dy_, hi.z);
          const double distance = std::max(glm::length(view.eye - glm::clamp(view.eye, block_lo, block_hi)), 1e-3);
          if (error / distance * view.pixels_per_radian > view.max_error_px) return true;
        }
      return false;
    };
    split = shows_too_much();
  }
  if (!split) {
    out.push_back({i0, j0, stride});
    return;
  }
  for (int c = 0; c < 4; ++c) visit(level - 1, 2 * ni + (c & 1), 2 * nj + (c >> 1), view, out);
}

}  // namespace skylit::view
