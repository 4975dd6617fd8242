// Point-in-solid for a closed mesh: the winding number along a ray straight up (+z),
// the sum over the triangles the ray crosses of the sign of their normal's z. One
// outward shell gives 1 inside and 0 outside; overlapping shells add, so "winding > 0"
// is the inside of their union.
#pragma once

#include "flight/mesh.h"
#include "flight/planar_triangle_grid.h"

#include <vector>

namespace skylit::flight {

class MeshInside {
 public:
  explicit MeshInside(const Mesh& mesh);  // keeps a reference: `mesh` must outlive this

  int winding_number(const glm::dvec3& p) const;
  bool operator()(const glm::dvec3& p) const { return winding_number(p) > 0; }

 private:
  const Mesh& mesh_;
  PlanarTriangleGrid grid_;
  std::vector<int> normal_z_sign_;
};

}  // namespace skylit::flight
