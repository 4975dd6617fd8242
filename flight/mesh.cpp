#include "flight/mesh.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace skylit::flight {

void Mesh::append(const Mesh& other) {
  const auto offset = static_cast<std::uint32_t>(vertices.size());
  vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
  for (const auto& t : other.triangles) triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
}

Bounds bounds(const Mesh& mesh) {
  Bounds b;
  if (mesh.vertices.empty()) return b;
  b.lo = glm::dvec3(std::numeric_limits<double>::infinity());
  b.hi = -b.lo;
  for (const auto& v : mesh.vertices) {
    b.lo = glm::min(b.lo, v);
    b.hi = glm::max(b.hi, v);
  }
  return b;
}

double signed_volume(const Mesh& mesh) {
  double six_v = 0.0;
  for (const auto& t : mesh.triangles)
    six_v += glm::dot(mesh.vertices[t[0]], glm::cross(mesh.vertices[t[1]], mesh.vertices[t[2]]));
  return six_v / 6.0;
}

bool is_closed(const Mesh& mesh) {
  if (mesh.triangles.empty()) return false;
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& t : mesh.triangles)
    for (int e = 0; e < 3; ++e)
      if (++directed[{t[e], t[(e + 1) % 3]}] > 1) return false;  // two triangles with the same a→b
  for (const auto& [edge, count] : directed)
    if (!directed.contains({edge.second, edge.first})) return false;
  return true;
}

void check_closed_mesh(const Mesh& mesh, const std::string& what) {
  if (mesh.triangles.empty()) throw MeshError(what + ": the mesh has no triangles");
  for (const auto& v : mesh.vertices)
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
      throw MeshError(what + ": a vertex is not finite");
  for (const auto& t : mesh.triangles)
    for (auto i : t)
      if (i >= mesh.vertices.size()) throw MeshError(what + ": a triangle indexes a missing vertex");
  if (!is_closed(mesh))
    throw MeshError(what + ": the mesh is not closed (every edge must border exactly two consistently oriented triangles)");
}

void flip_orientation(Mesh& mesh) {
  for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
}

}  // namespace skylit::flight
