// Ground-truth visibility for a receiver: a horizon elevation σ(φ) (occluded
// iff elevation e ≤ σ(φ), math-notes §0) and any number of spherical caps.
// Integrals are exact in elevation per azimuth (Gauss–Legendre on each visible
// interval, split at the kink of a clamped cosine) and use a midpoint rule in
// azimuth — the oracle for every SH and shading test (math-notes §1, §8).
#pragma once

#include "shading/sh/sh_basis.h"

#include <functional>
#include <optional>
#include <utility>
#include <vector>

namespace skylit::shading {

// Directions within half_angle of axis (unit) are occluded.
struct Cap {
  glm::dvec3 axis;
  double half_angle;
};

struct Occluders {
  // Horizon elevation σ(φ) in radians, φ in the math frame (from +x toward +y).
  // Empty: no horizon at all (the whole sphere is visible but for the caps).
  std::function<double(double phi)> horizon;
  std::vector<Cap> caps;
};

using Interval = std::pair<double, double>;  // elevations [e0, e1], e0 < e1

// Visible elevation intervals in [−π/2, π/2] along azimuth φ, sorted.
std::vector<Interval> visible_intervals(const Occluders& occ, double phi);

struct IntegrationOptions {
  int azimuths = 2048;   // midpoint rule in φ
  int gauss_nodes = 16;  // per visible sub-interval
  // If set, the integrand contains max(n·ω, 0): intervals are split at its kink.
  std::optional<glm::dvec3> clamped_cosine_normal;
};

// ∫_{S²} g(ω)·V(ω) dω.
double integrate(const Occluders& occ, const std::function<double(const glm::dvec3&)>& g,
                 const IntegrationOptions& opt = {});

// SH projection of the binary visibility V (T0 of math-notes §6).
sh::Vec project_visibility(int order, const Occluders& occ, const IntegrationOptions& opt = {});

// (1/π)∫ V(ω) max(n·ω, 0) dω over the whole sphere. For the `skyview` product
// (sky only above the horizontal) pass a horizon clamped at 0.
double cosine_weighted_visibility(const Occluders& occ, const glm::dvec3& normal, int azimuths = 2048);

}  // namespace skylit::shading
