// An aircraft as a set of spheres in its body frame (DESIGN.md "Aircraft"; seed 000
// approximates dynamic blockers by spheres), its JSON file, and its placement at a pose.
#pragma once

#include "flight/pose.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace skylit::flight {

// Body frame: x forward, y left, z up, metres, origin at the aircraft's reference point
// (≈ its centre of mass).
struct BodySphere {
  glm::dvec3 centre{0.0};
  double radius = 0.0;
};

// How well the spheres stand for the mesh they were fitted to (sphere_fit.h).
struct FitErrorSummary {
  double volume_error = 0.0;     // |union of spheres Δ mesh| / |mesh| (symmetric difference)
  double volume_error_se = 0.0;  // its Monte Carlo standard error
  long long volume_samples = 0;
  double solid_angle_error = 0.0;  // the largest |Ω_spheres − Ω_mesh| / Ω_mesh over the viewpoints
  long long solid_angle_rays = 0;  // per viewpoint
};

struct SphereSet {
  std::string name;
  std::vector<BodySphere> spheres;
  double span_m = 0.0;    // extent along y (wing span, rotor diameter)
  double length_m = 0.0;  // extent along x
  double height_m = 0.0;  // extent along z
  std::string source;     // where the mesh came from and how it was fitted
  bool has_fit_error = false;
  FitErrorSummary fit_error;
};

// Bad sphere-set files: one line naming the file and what is wrong.
class SphereSetError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// More spheres than any aircraft needs (seed 000's scenes use tens to hundreds); a file
// above it is taken as a mistake rather than loaded.
constexpr std::size_t kMaxSpheres = 100'000;

// Parses and validates (`origin` names the text in errors): an object with "name" and a
// non-empty "spheres" array of {"centre": [x, y, z], "radius": r}, r > 0, all finite.
SphereSet parse_sphere_set(const std::string& json_text, const std::string& origin);
SphereSet read_sphere_set(const std::string& path);
std::string sphere_set_json(const SphereSet& set);  // pretty-printed, ends with a newline

// A sphere in the pose's frame: x east, y north, z up, metres.
struct PlacedSphere {
  glm::dvec3 centre{0.0};
  double radius = 0.0;
};

// centre = pose.position + body_to_enu(pose.attitude) · body centre; radii unchanged.
std::vector<PlacedSphere> place(const SphereSet& set, const Pose& pose);

}  // namespace skylit::flight
