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
  build_parents(ni0, nj0, ni1, nj1);
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
        for (int cj = 2 * nj; cj <= std::min(2 * nj + 1, child.nodes_y - 1); ++cj)
          for (int ci = 2 * ni; ci <= std::min(2 * ni + 1, child.nodes_x - 1); ++ci) {
            const glm::vec2 c = child.range[static_cast<std::size_t>(cj) * child.nodes_x + ci];
            r = {std::min(r.x, c.x), std::max(r.y, c.y)};
          }
        level.range[static_cast<std::size_t>(nj) * level.nodes_x + ni] = r;
      }
  }
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
    const glm::dvec3 nearest = glm::clamp(view.eye, lo, hi);
    const double distance = std::max(glm::length(view.eye - nearest), 1e-3);
    const double spacing = stride * std::max(dx_, dy_);
    split = spacing / distance * view.pixels_per_radian > view.max_error_px;
  }
  if (!split) {
    out.push_back({i0, j0, stride});
    return;
  }
  for (int c = 0; c < 4; ++c) visit(level - 1, 2 * ni + (c & 1), 2 * nj + (c >> 1), view, out);
}

}  // namespace skylit::view
