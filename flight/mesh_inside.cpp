#include "flight/mesh_inside.h"

#include <glm/geometric.hpp>

namespace skylit::flight {
namespace {

std::vector<PlanarTriangle> projected_to_xy(const Mesh& mesh) {
  std::vector<PlanarTriangle> out;
  out.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    out.push_back({glm::dvec2(mesh.vertices[t[0]]), glm::dvec2(mesh.vertices[t[1]]), glm::dvec2(mesh.vertices[t[2]])});
  return out;
}

}  // namespace

MeshInside::MeshInside(const Mesh& mesh) : mesh_(mesh), grid_(projected_to_xy(mesh)) {
  normal_z_sign_.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    const glm::dvec3& a = mesh.vertices[t[0]];
    const double nz = glm::cross(mesh.vertices[t[1]] - a, mesh.vertices[t[2]] - a).z;
    normal_z_sign_.push_back(nz > 0.0 ? 1 : (nz < 0.0 ? -1 : 0));
  }
}

int MeshInside::winding_number(const glm::dvec3& p) const {
  thread_local std::vector<std::uint32_t> hits;
  grid_.containing(glm::dvec2(p), hits);
  int winding = 0;
  glm::dvec3 w;
  for (std::uint32_t k : hits) {
    barycentric(grid_.triangle(k), glm::dvec2(p), w);
    const auto& t = mesh_.triangles[k];
    const double z = w.x * mesh_.vertices[t[0]].z + w.y * mesh_.vertices[t[1]].z + w.z * mesh_.vertices[t[2]].z;
    if (z > p.z) winding += normal_z_sign_[k];
  }
  return winding;
}

}  // namespace skylit::flight
