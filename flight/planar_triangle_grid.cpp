#include "flight/planar_triangle_grid.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace skylit::flight {
namespace {

double cross2(const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; }

}  // namespace

bool barycentric(const PlanarTriangle& t, const glm::dvec2& q, glm::dvec3& w) {
  const double area = cross2(t[1] - t[0], t[2] - t[0]);
  if (area == 0.0 || !std::isfinite(area)) return false;
  w.x = cross2(t[1] - q, t[2] - q) / area;
  w.y = cross2(t[2] - q, t[0] - q) / area;
  w.z = 1.0 - w.x - w.y;
  return w.x >= 0.0 && w.y >= 0.0 && w.z >= 0.0;
}

PlanarTriangleGrid::PlanarTriangleGrid(std::vector<PlanarTriangle> triangles) : triangles_(std::move(triangles)) {
  if (triangles_.empty()) return;
  glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const auto& t : triangles_)
    for (const auto& p : t) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  // About two triangles per cell on average over the bounding square's cells.
  const int n = std::clamp(static_cast<int>(std::sqrt(triangles_.size() / 2.0)), 1, 1024);
  nx_ = ny_ = n;
  lo_ = lo;
  cell_size_ = glm::max((hi - lo) / static_cast<double>(n), glm::dvec2(1e-300));
  auto cell_range = [&](const PlanarTriangle& t, int& i0, int& i1, int& j0, int& j1) {
    const glm::dvec2 tlo = glm::min(t[0], glm::min(t[1], t[2])), thi = glm::max(t[0], glm::max(t[1], t[2]));
    i0 = std::clamp(static_cast<int>((tlo.x - lo_.x) / cell_size_.x), 0, nx_ - 1);
    i1 = std::clamp(static_cast<int>((thi.x - lo_.x) / cell_size_.x), 0, nx_ - 1);
    j0 = std::clamp(static_cast<int>((tlo.y - lo_.y) / cell_size_.y), 0, ny_ - 1);
    j1 = std::clamp(static_cast<int>((thi.y - lo_.y) / cell_size_.y), 0, ny_ - 1);
  };
  std::vector<std::uint32_t> count(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
  int i0, i1, j0, j1;
  for (const auto& t : triangles_) {
    cell_range(t, i0, i1, j0, j1);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) ++count[static_cast<std::size_t>(j) * nx_ + i + 1];
  }
  for (std::size_t c = 1; c < count.size(); ++c) count[c] += count[c - 1];
  cell_start_ = count;
  items_.resize(count.back());
  for (std::uint32_t k = 0; k < triangles_.size(); ++k) {
    cell_range(triangles_[k], i0, i1, j0, j1);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) items_[count[static_cast<std::size_t>(j) * nx_ + i]++] = k;
  }
}

bool PlanarTriangleGrid::cell_of(const glm::dvec2& q, std::size_t& cell) const {
  if (nx_ == 0) return false;
  const glm::dvec2 f = (q - lo_) / cell_size_;
  if (!(f.x >= 0.0 && f.y >= 0.0 && f.x <= nx_ && f.y <= ny_)) return false;
  const int i = std::min(static_cast<int>(f.x), nx_ - 1), j = std::min(static_cast<int>(f.y), ny_ - 1);
  cell = static_cast<std::size_t>(j) * nx_ + i;
  return true;
}

void PlanarTriangleGrid::containing(const glm::dvec2& q, std::vector<std::uint32_t>& out) const {
  out.clear();
  std::size_t c;
  if (!cell_of(q, c)) return;
  glm::dvec3 w;
  for (std::uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k)
    if (barycentric(triangles_[items_[k]], q, w)) out.push_back(items_[k]);
}

bool PlanarTriangleGrid::any_contains(const glm::dvec2& q) const {
  std::size_t c;
  if (!cell_of(q, c)) return false;
  glm::dvec3 w;
  for (std::uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k)
    if (barycentric(triangles_[items_[k]], q, w)) return true;
  return false;
}

}  // namespace skylit::flight
