#include "shading/blockers/disc_occlusion.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace skylit::blockers {
namespace {

constexpr double kPi = std::numbers::pi;

constexpr int kMaxAnalyticOverlaps = 8;  // kept without allocation; more go to a vector

double cap_area(double half_angle) { return 2.0 * kPi * (1.0 - std::cos(half_angle)); }
double clamped_acos(double x) { return std::acos(std::clamp(x, -1.0, 1.0)); }

// Unit vectors e1, e2 completing the unit axis w to an orthonormal frame.
void frame_around(const glm::dvec3& w, glm::dvec3& e1, glm::dvec3& e2) {
  const glm::dvec3 helper = std::abs(w.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  e1 = glm::normalize(glm::cross(helper, w));
  e2 = glm::cross(w, e1);
}

}  // namespace

double cap_intersection_area(double a, double b, double c) {
  if (!(a > 0.0) || !(b > 0.0) || c >= a + b) return 0.0;
  if (c <= std::abs(a - b)) return cap_area(std::min(a, b));  // one inside the other
  // Two caps whose boundaries cross: the lune between the two arcs, by Gauss–Bonnet
  // (Tovchigrechko & Vakser 2001, eq. 2). Both caps are at most hemispheres here.
  const double ca = std::cos(a), cb = std::cos(b), cc = std::cos(c);
  const double sa = std::sin(a), sb = std::sin(b), sc = std::sin(c);
  const double area = 2.0 * (kPi - clamped_acos((cc - ca * cb) / (sa * sb)) -
                             ca * clamped_acos((cb - ca * cc) / (sa * sc)) -
                             cb * clamped_acos((ca - cb * cc) / (sb * sc)));
  return std::clamp(area, 0.0, cap_area(std::min(a, b)));
}

double disc_fraction_left(std::span<const Sphere> spheres, std::span<const std::uint32_t> candidates,
                          const glm::dvec3& p, const glm::dvec3& sun, double disc_radius) {
  // The spheres over the disc: one is exact by the cap intersection; several overlap one
  // another in ways no product of shares follows (400 coincident spheres each covering
  // a fifth of the disc leave four fifths, not 0.8⁴⁰⁰), so their union is sampled.
  std::array<Sphere, kMaxAnalyticOverlaps> over{};
  std::vector<Sphere> many;
  int count = 0;
  double left = 1.0;
  for (std::uint32_t k : candidates) {
    const Sphere& s = spheres[k];
    const glm::dvec3 to_c = s.centre - p;
    const double d = glm::length(to_c);
    if (d <= s.radius) return 0.0;  // inside the blocker
    const double half = std::asin(s.radius / d);
    const double sep = clamped_acos(glm::dot(to_c / d, sun));
    if (sep >= half + disc_radius) continue;
    if (count == 0) left = 1.0 - std::min(cap_intersection_area(disc_radius, half, sep) / cap_area(disc_radius), 1.0);
    if (count < kMaxAnalyticOverlaps) over[count] = s;
    if (count == kMaxAnalyticOverlaps) many.assign(over.begin(), over.end());
    if (count >= kMaxAnalyticOverlaps) many.push_back(s);
    ++count;
  }
  if (count <= 1) return left;
  const std::span<const Sphere> union_of = many.empty() ? std::span<const Sphere>(over.data(), count) : many;
  return disc_fraction_sampled(union_of, p, sun, disc_radius, kDiscUnionSamples);
}

bool ray_hits_sphere(const Sphere& s, const glm::dvec3& p, const glm::dvec3& dir) {
  const glm::dvec3 to_c = s.centre - p;
  const double along = glm::dot(to_c, dir);
  const double miss2 = glm::dot(to_c, to_c) - along * along;  // squared distance of the line from the centre
  if (miss2 > s.radius * s.radius) return false;
  return along > 0.0 || glm::dot(to_c, to_c) <= s.radius * s.radius;
}

double disc_fraction_sampled(std::span<const Sphere> spheres, const glm::dvec3& p, const glm::dvec3& sun,
                             double disc_radius, int samples) {
  glm::dvec3 e1, e2;
  frame_around(sun, e1, e2);
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  const double cos_r = std::cos(disc_radius);
  int open = 0;
  for (int k = 0; k < samples; ++k) {
    // Equal solid angle per sample: cos θ uniform in [cos r, 1].
    const double cos_t = 1.0 - (1.0 - cos_r) * (k + 0.5) / samples;
    const double sin_t = std::sqrt(std::max(0.0, 1.0 - cos_t * cos_t));
    const double phi = golden * k;
    const glm::dvec3 dir = cos_t * sun + sin_t * (std::cos(phi) * e1 + std::sin(phi) * e2);
    bool blocked = false;
    for (const Sphere& s : spheres)
      if (ray_hits_sphere(s, p, dir)) {
        blocked = true;
        break;
      }
    open += blocked ? 0 : 1;
  }
  return static_cast<double>(open) / samples;
}

}  // namespace skylit::blockers
