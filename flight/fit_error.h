// How far a sphere set is from the mesh it stands for, measured the two ways that matter
// for its shadow: the volume where they disagree, and the solid angle they block as
// seen from the ground (the sky light a receiver loses is an integral over that angle).
#pragma once

#include "flight/mesh.h"
#include "flight/sphere_set.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace skylit::flight {

using PointTest = std::function<bool(const glm::dvec3&)>;

bool inside_any(const std::vector<BodySphere>& spheres, const glm::dvec3& p);

// Bounds of the spheres, and of a mesh's vertices together with spheres.
Bounds bounds(const std::vector<BodySphere>& spheres);
Bounds bounds(const Mesh& mesh, const std::vector<BodySphere>& spheres);

// Monte Carlo over `samples` points uniform in `box` (which must hold both solids):
// |A|, |B| and |A Δ B|, each with its standard error, and |A Δ B| / |A| with the
// standard error of that ratio estimator (A's volume comes from the same points).
struct VolumeComparison {
  long long samples = 0;
  double volume_a = 0.0, volume_a_se = 0.0;
  double volume_b = 0.0, volume_b_se = 0.0;
  double symmetric_difference = 0.0, symmetric_difference_se = 0.0;
  double relative = 0.0, relative_se = 0.0;
};
VolumeComparison compare_volumes(const PointTest& in_a, const PointTest& in_b, const Bounds& box, long long samples,
                                 std::uint64_t seed);

// Where the ground sees the aircraft from: `eye` in the body frame (level flight).
struct Viewpoint {
  std::string label;
  glm::dvec3 eye{0.0};
};
// 100 m and 1000 m from the reference point, straight below it and 45° off to its right
// (−y) side: a receiver under the aircraft and one seeing it at half height in the sky.
std::vector<Viewpoint> standard_viewpoints();

// Rays from the eye, uniform in solid angle over the cone that just holds the mesh and
// the spheres; the same rays test both, so the difference has a small variance.
struct SolidAngleComparison {
  Viewpoint view;
  long long rays = 0;
  double mesh_sr = 0.0, spheres_sr = 0.0;  // steradians blocked by each
  double difference_sr = 0.0, difference_se_sr = 0.0;  // Ω_spheres − Ω_mesh and its standard error
  double mismatch_sr = 0.0;  // directions blocked by exactly one of them
  double relative() const { return mesh_sr > 0.0 ? difference_sr / mesh_sr : 0.0; }
};
// Throws MeshError when the eye is within the bounding sphere of mesh and spheres.
SolidAngleComparison compare_solid_angles(const Mesh& mesh, const std::vector<BodySphere>& spheres, const Viewpoint& view,
                                          long long rays, std::uint64_t seed);

}  // namespace skylit::flight
