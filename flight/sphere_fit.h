// Fitting K spheres to a closed mesh, as seed 000 does ("we simply apply a k-means
// clustering in order to approximate our dynamic objects with spherical blockers"):
// points uniform inside the solid, k-means (k-means++ seeding, Lloyd iterations), a
// radius per cluster, then the fit's error measured (fit_error.h).
#pragma once

#include "flight/fit_error.h"
#include "flight/mesh.h"
#include "flight/sphere_set.h"

#include <cstdint>
#include <vector>

namespace skylit::flight {

// How each cluster's radius is chosen (derivations in sphere_fit.cpp).
enum class RadiusRule {
  kHalfSolidShell,  // minimise the cluster's own symmetric difference: the radius where
                    // half of the sphere's surface (within its Voronoi cell) lies in the solid
  kVolumeShare,     // the sphere's volume equals its cluster's share of the solid's volume
  kPlanformArea,    // the sphere's disc equals its cluster's area seen from above (the
                    // body's x-y plane): what the shadows below see of thin wings
};

struct FitOptions {
  int k = 30;
  long long samples = 100'000;  // points inside the solid for the clustering
  std::uint64_t seed = 1;
  int max_iterations = 200;     // Lloyd iterations (it stops earlier once no point moves)
  RadiusRule radius_rule = RadiusRule::kHalfSolidShell;
  long long error_samples = 2'000'000;  // points in the bounding box for the volume error
  long long error_rays = 200'000;       // rays per viewpoint for the solid-angle error
};

class FitError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

struct FitReport {
  VolumeComparison volume;  // A = mesh, B = union of spheres
  std::vector<SolidAngleComparison> views;
  double worst_solid_angle_error() const;  // max |relative()| over the views
  FitErrorSummary summary() const;
};

struct SphereFit {
  std::vector<BodySphere> spheres;
  int iterations = 0;  // Lloyd iterations run
  FitReport report;
};

// Throws FitError for k < 1, k > kMaxSpheres or samples < k, and MeshError for a mesh
// that is not closed or encloses nothing.
SphereFit fit_spheres(const Mesh& mesh, const FitOptions& options);

// The error of any sphere set against the mesh, with options' error_samples, error_rays
// and seed (a stream apart from the fit's).
FitReport measure_fit(const Mesh& mesh, const std::vector<BodySphere>& spheres, const FitOptions& options);

}  // namespace skylit::flight
