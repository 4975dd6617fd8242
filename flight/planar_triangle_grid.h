// Triangles in a plane, bucketed in a uniform grid so that "which triangles contain this
// point" costs a few tests instead of one per triangle. Both the point-inside test (ray
// parity along z) and the solid-angle rays (triangles projected from an eye) reduce to it.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace skylit::flight {

using PlanarTriangle = std::array<glm::dvec2, 3>;

class PlanarTriangleGrid {
 public:
  explicit PlanarTriangleGrid(std::vector<PlanarTriangle> triangles);

  // Indices of the triangles whose closed area contains q (degenerate ones never do).
  // `out` is cleared first; reusing it avoids an allocation per query.
  void containing(const glm::dvec2& q, std::vector<std::uint32_t>& out) const;
  bool any_contains(const glm::dvec2& q) const;

  const PlanarTriangle& triangle(std::uint32_t i) const { return triangles_[i]; }

 private:
  bool cell_of(const glm::dvec2& q, std::size_t& cell) const;

  std::vector<PlanarTriangle> triangles_;
  glm::dvec2 lo_{0.0}, cell_size_{1.0};
  int nx_ = 0, ny_ = 0;
  std::vector<std::uint32_t> cell_start_;  // CSR: cell c holds items[cell_start_[c] .. cell_start_[c+1])
  std::vector<std::uint32_t> items_;
};

// Barycentric coordinates of q in t; false when t is degenerate or q lies outside it.
bool barycentric(const PlanarTriangle& t, const glm::dvec2& q, glm::dvec3& weights);

}  // namespace skylit::flight
