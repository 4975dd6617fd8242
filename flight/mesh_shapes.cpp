#include "flight/mesh_shapes.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <algorithm>
#include <map>
#include <numbers>
#include <utility>

namespace skylit::flight {

void orient_outward(Mesh& mesh) {
  if (signed_volume(mesh) < 0.0) flip_orientation(mesh);
}

Mesh loft(const std::vector<std::vector<glm::dvec3>>& rings) {
  Mesh m;
  if (rings.size() < 2 || rings.front().size() < 3) throw MeshError("a loft needs two rings of at least three points");
  const auto n = static_cast<std::uint32_t>(rings.front().size());
  for (const auto& ring : rings) {
    if (ring.size() != n) throw MeshError("a loft's rings must have the same number of points");
    m.vertices.insert(m.vertices.end(), ring.begin(), ring.end());
  }
  for (std::uint32_t r = 0; r + 1 < rings.size(); ++r)
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t a = r * n + i, b = r * n + (i + 1) % n, c = a + n, d = b + n;
      m.triangles.push_back({a, b, d});
      m.triangles.push_back({a, d, c});
    }
  auto cap = [&](std::uint32_t first, bool reverse) {
    glm::dvec3 centroid(0.0);
    for (std::uint32_t i = 0; i < n; ++i) centroid += m.vertices[first + i];
    const auto c = static_cast<std::uint32_t>(m.vertices.size());
    m.vertices.push_back(centroid / static_cast<double>(n));
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t a = first + i, b = first + (i + 1) % n;
      m.triangles.push_back(reverse ? std::array{c, a, b} : std::array{c, b, a});
    }
  };
  cap(0, false);
  cap(static_cast<std::uint32_t>(rings.size() - 1) * n, true);
  orient_outward(m);
  return m;
}

Mesh transformed(Mesh mesh, const glm::dmat3& rotation, const glm::dvec3& offset) {
  for (auto& v : mesh.vertices) v = rotation * v + offset;
  return mesh;
}

Mesh make_box(const glm::dvec3& lo, const glm::dvec3& hi) {
  auto ring = [&](double z) {
    return std::vector<glm::dvec3>{{lo.x, lo.y, z}, {hi.x, lo.y, z}, {hi.x, hi.y, z}, {lo.x, hi.y, z}};
  };
  return loft({ring(lo.z), ring(hi.z)});
}

Mesh make_prism(double radius, double height, int sides) {
  auto ring = [&](double z) {
    std::vector<glm::dvec3> r;
    for (int i = 0; i < sides; ++i) {
      const double t = 2.0 * std::numbers::pi * i / sides;
      r.push_back({radius * std::cos(t), radius * std::sin(t), z});
    }
    return r;
  };
  return loft({ring(0.0), ring(height)});
}

Mesh make_icosphere(double radius, int subdivisions) {
  const double g = std::numbers::phi;
  Mesh m;
  for (const auto& v : std::vector<glm::dvec3>{{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                                               {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}})
    m.vertices.push_back(glm::normalize(v) * radius);
  m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoint;
    auto mid = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      if (auto it = midpoint.find(key); it != midpoint.end()) return it->second;
      m.vertices.push_back(glm::normalize(m.vertices[a] + m.vertices[b]) * radius);
      return midpoint[key] = static_cast<std::uint32_t>(m.vertices.size() - 1);
    };
    std::vector<std::array<std::uint32_t, 3>> next;
    for (const auto& t : m.triangles) {
      const std::uint32_t ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
      for (const auto& f : {std::array{t[0], ab, ca}, std::array{t[1], bc, ab}, std::array{t[2], ca, bc}, std::array{ab, bc, ca}})
        next.push_back(f);
    }
    m.triangles = std::move(next);
  }
  orient_outward(m);
  return m;
}

}  // namespace skylit::flight
