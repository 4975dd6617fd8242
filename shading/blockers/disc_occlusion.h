// The sun disc behind sphere blockers (DESIGN.md "Aircraft", Sun): the fraction of the
// disc a set of spheres leaves visible from a receiver, from the exact area of
// intersection of two spherical caps; and the same by sampling the disc (the truth).
#pragma once

#include "shading/blockers/sphere_blocker.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>

namespace skylit::blockers {

// Area (sr) of the intersection of two caps on the unit sphere with half-angles
// a, b ∈ [0, π/2] whose axes are `separation` (rad, [0, π]) apart.
double cap_intersection_area(double a, double b, double separation);

// Disc samples where several spheres overlap the disc (the union's error ≲ 1/√N in the
// penumbra only: a disc wholly covered or wholly open is exact).
inline constexpr int kDiscUnionSamples = 256;

// Fraction of the sun disc (axis `sun`, unit; angular radius `disc_radius`) not
// covered by any sphere, seen from p: exact (cap intersection) where at most one sphere
// meets the disc, the union sampled at kDiscUnionSamples points where several do. A
// receiver inside a sphere sees no sun (0).
// Only the spheres listed in `candidates` are tested.
double disc_fraction_left(std::span<const Sphere> spheres, std::span<const std::uint32_t> candidates,
                          const glm::dvec3& p, const glm::dvec3& sun, double disc_radius);

// The truth: the share of `samples` uniformly spread points of the disc (a Fibonacci
// spiral in solid angle) whose rays from p miss every sphere.
double disc_fraction_sampled(std::span<const Sphere> spheres, const glm::dvec3& p, const glm::dvec3& sun,
                             double disc_radius, int samples);

// Whether the ray p + t·dir (t > 0, dir unit) meets the sphere.
bool ray_hits_sphere(const Sphere& s, const glm::dvec3& p, const glm::dvec3& dir);

}  // namespace skylit::blockers
