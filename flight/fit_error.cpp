#include "flight/fit_error.h"

#include "flight/planar_triangle_grid.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

namespace skylit::flight {

bool inside_any(const std::vector<BodySphere>& spheres, const glm::dvec3& p) {
  for (const auto& s : spheres) {
    const glm::dvec3 d = p - s.centre;
    if (glm::dot(d, d) <= s.radius * s.radius) return true;
  }
  return false;
}

Bounds bounds(const std::vector<BodySphere>& spheres) {
  Bounds b;
  if (spheres.empty()) return b;
  b.lo = glm::dvec3(std::numeric_limits<double>::infinity());
  b.hi = -b.lo;
  for (const auto& s : spheres) {
    b.lo = glm::min(b.lo, s.centre - s.radius);
    b.hi = glm::max(b.hi, s.centre + s.radius);
  }
  return b;
}

Bounds bounds(const Mesh& mesh, const std::vector<BodySphere>& spheres) {
  Bounds b = bounds(mesh);
  if (spheres.empty()) return b;
  const Bounds s = bounds(spheres);
  return {glm::min(b.lo, s.lo), glm::max(b.hi, s.hi)};
}

VolumeComparison compare_volumes(const PointTest& in_a, const PointTest& in_b, const Bounds& box, long long samples,
                                 std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  long long na = 0, nb = 0, nx = 0;
  for (long long i = 0; i < samples; ++i) {
    const glm::dvec3 p = box.lo + glm::dvec3(u(rng), u(rng), u(rng)) * box.size();
    const bool a = in_a(p), b = in_b(p);
    na += a;
    nb += b;
    nx += a != b;
  }
  VolumeComparison c;
  c.samples = samples;
  const double n = static_cast<double>(samples), vbox = box.volume();
  auto mean_and_se = [&](long long hits, double& v, double& se) {
    const double p = hits / n;
    v = vbox * p;
    se = vbox * std::sqrt(p * (1.0 - p) / n);
  };
  mean_and_se(na, c.volume_a, c.volume_a_se);
  mean_and_se(nb, c.volume_b, c.volume_b_se);
  mean_and_se(nx, c.symmetric_difference, c.symmetric_difference_se);
  if (na > 0) {
    // Ratio R = Σx/Σa of indicators x = [a≠b] and a; its delta-method variance is
    // Var(x − R·a) / (n·mean(a)²), and Σ(x − R·a)² = nx − 2R·n(x∧a) + R²·na with
    // x∧a = a∧¬b, counted as na − n(a∧b) = (na + nb − nx) / 2 subtracted from na.
    const double r = static_cast<double>(nx) / na;
    const double n_a_not_b = na - (na + nb - nx) / 2.0;
    const double ss = nx - 2.0 * r * n_a_not_b + r * r * na;
    const double mean_a = na / n;
    c.relative = r;
    c.relative_se = std::sqrt(std::max(0.0, ss / (n - 1.0)) / n) / mean_a;
  }
  return c;
}

std::vector<Viewpoint> standard_viewpoints() {
  const double s = std::numbers::sqrt2 / 2.0;
  return {{"100 m below", {0.0, 0.0, -100.0}},
          {"100 m at 45 deg", {0.0, -100.0 * s, -100.0 * s}},
          {"1000 m below", {0.0, 0.0, -1000.0}},
          {"1000 m at 45 deg", {0.0, -1000.0 * s, -1000.0 * s}}};
}

SolidAngleComparison compare_solid_angles(const Mesh& mesh, const std::vector<BodySphere>& spheres, const Viewpoint& view,
                                          long long rays, std::uint64_t seed) {
  // The cone: the sphere about the joint bounding box's centre that holds every vertex
  // and every sphere, seen from the eye.
  const Bounds box = bounds(mesh, spheres);
  const glm::dvec3 centre = 0.5 * (box.lo + box.hi);
  double reach = 0.0;
  for (const auto& v : mesh.vertices) reach = std::max(reach, glm::length(v - centre));
  for (const auto& s : spheres) reach = std::max(reach, glm::length(s.centre - centre) + s.radius);
  const glm::dvec3 to_centre = centre - view.eye;
  const double dist = glm::length(to_centre);
  if (!(dist > reach * 1.001))
    throw MeshError("viewpoint '" + view.label + "' is inside the aircraft's bounding sphere");
  const double cos_alpha = std::sqrt(1.0 - (reach / dist) * (reach / dist));
  const double cone_sr = 2.0 * std::numbers::pi * (1.0 - cos_alpha);
  const glm::dvec3 w = to_centre / dist;
  const glm::dvec3 helper = std::abs(w.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  const glm::dvec3 u = glm::normalize(glm::cross(helper, w)), v = glm::cross(w, u);

  // Every vertex lies in front of the eye (inside the cone), so a ray meets a triangle
  // exactly when its gnomonic (central) projection lies in the projected triangle.
  auto gnomonic = [&](const glm::dvec3& p) {
    const glm::dvec3 d = p - view.eye;
    return glm::dvec2(glm::dot(d, u), glm::dot(d, v)) / glm::dot(d, w);
  };
  std::vector<PlanarTriangle> projected;
  projected.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    projected.push_back({gnomonic(mesh.vertices[t[0]]), gnomonic(mesh.vertices[t[1]]), gnomonic(mesh.vertices[t[2]])});
  const PlanarTriangleGrid grid(std::move(projected));

  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  long long hit_mesh = 0, hit_spheres = 0, mismatch = 0;
  for (long long i = 0; i < rays; ++i) {
    const double cos_t = 1.0 - uni(rng) * (1.0 - cos_alpha), sin_t = std::sqrt(std::max(0.0, 1.0 - cos_t * cos_t));
    const double phi = 2.0 * std::numbers::pi * uni(rng);
    const glm::dvec2 q(sin_t / cos_t * std::cos(phi), sin_t / cos_t * std::sin(phi));
    const glm::dvec3 dir = cos_t * w + sin_t * (std::cos(phi) * u + std::sin(phi) * v);
    const bool m = grid.any_contains(q);
    bool s = false;
    for (const auto& sp : spheres) {
      const glm::dvec3 c = sp.centre - view.eye;
      const double along = glm::dot(c, dir), c2 = glm::dot(c, c), r2 = sp.radius * sp.radius;
      if (c2 <= r2 || (along > 0.0 && c2 - along * along <= r2)) {
        s = true;
        break;
      }
    }
    hit_mesh += m;
    hit_spheres += s;
    mismatch += m != s;
  }
  SolidAngleComparison c;
  c.view = view;
  c.rays = rays;
  const double n = static_cast<double>(rays);
  c.mesh_sr = cone_sr * hit_mesh / n;
  c.spheres_sr = cone_sr * hit_spheres / n;
  c.mismatch_sr = cone_sr * mismatch / n;
  // x = s − m ∈ {−1, 0, 1}: E[x] = (hs − hm)/n, E[x²] = mismatch/n.
  const double mean = (hit_spheres - hit_mesh) / n, mean_sq = mismatch / n;
  c.difference_sr = cone_sr * mean;
  c.difference_se_sr = cone_sr * std::sqrt(std::max(0.0, mean_sq - mean * mean) / n);
  return c;
}

}  // namespace skylit::flight
