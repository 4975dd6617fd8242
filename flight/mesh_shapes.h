// Closed meshes built from shapes: lofts through rings (the aircraft parts) and the
// solids whose volumes have closed forms (boxes, prisms, icospheres) for the tests.
#pragma once

#include "flight/mesh.h"

#include <glm/mat3x3.hpp>

#include <vector>

namespace skylit::flight {

// Joins consecutive rings (closed loops with the same number of points) by quads and
// caps the first and last by a fan to their centroids; oriented outward.
Mesh loft(const std::vector<std::vector<glm::dvec3>>& rings);

// Flips the mesh when its signed volume is negative (one shell).
void orient_outward(Mesh& mesh);

// p → rotation · p + offset for every vertex (a proper rotation keeps the orientation).
Mesh transformed(Mesh mesh, const glm::dmat3& rotation, const glm::dvec3& offset);

Mesh make_box(const glm::dvec3& lo, const glm::dvec3& hi);
// A regular n-gon prism about the z axis from z = 0 to height, vertices at `radius`.
Mesh make_prism(double radius, double height, int sides);
// The icosahedron with vertices at `radius`, each face split into 4^subdivisions with
// the new vertices pushed out to the sphere.
Mesh make_icosphere(double radius, int subdivisions);

}  // namespace skylit::flight
