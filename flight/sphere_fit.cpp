#include "flight/sphere_fit.h"

#include "flight/mesh_inside.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>

namespace skylit::flight {
namespace {

// Streams of the one seed: the clustering's points, the outside points of the radius
// rule, and the error estimates are independent of each other.
constexpr std::uint64_t kOutsideStream = 0x9e3779b97f4a7c15ULL, kErrorStream = 0xbf58476d1ce4e5b9ULL;
// Rejection sampling gives up below this fill of the bounding box (a mesh that is inside
// out, or almost empty).
constexpr long long kMaxAttemptsPerSample = 10'000;
// Points outside the solid sampled for the half-solid-shell rule, per point inside.
constexpr long long kOutsidePerInside = 4;

double distance2(const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 d = a - b;
  return glm::dot(d, d);
}

std::size_t nearest(const std::vector<glm::dvec3>& centres, const glm::dvec3& p) {
  std::size_t best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t c = 0; c < centres.size(); ++c)
    if (const double d = distance2(centres[c], p); d < best_d) best_d = d, best = c;
  return best;
}

struct InteriorSample {
  std::vector<glm::dvec3> points;
  long long attempts = 0;  // box points drawn to get them: density = attempts / box volume
};

InteriorSample sample_interior(const MeshInside& inside, const Bounds& box, long long count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  InteriorSample s;
  s.points.reserve(static_cast<std::size_t>(count));
  while (static_cast<long long>(s.points.size()) < count) {
    if (s.attempts > count * kMaxAttemptsPerSample)
      throw MeshError("the mesh encloses (almost) no volume: is it inside out?");
    const glm::dvec3 p = box.lo + glm::dvec3(u(rng), u(rng), u(rng)) * box.size();
    ++s.attempts;
    if (inside(p)) s.points.push_back(p);
  }
  return s;
}

// k-means++ (Arthur & Vassilvitskii 2007): each new centre drawn with probability ∝ the
// squared distance to the nearest centre so far, which spreads the seeds over the solid.
std::vector<glm::dvec3> seed_centres(const std::vector<glm::dvec3>& pts, int k, std::mt19937_64& rng) {
  std::vector<glm::dvec3> centres{pts[std::uniform_int_distribution<std::size_t>(0, pts.size() - 1)(rng)]};
  std::vector<double> d2(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) d2[i] = distance2(pts[i], centres[0]);
  while (static_cast<int>(centres.size()) < k) {
    std::discrete_distribution<std::size_t> pick(d2.begin(), d2.end());
    centres.push_back(pts[pick(rng)]);
    for (std::size_t i = 0; i < pts.size(); ++i) d2[i] = std::min(d2[i], distance2(pts[i], centres.back()));
  }
  return centres;
}

// Lloyd: assign to the nearest centre, move each centre to its cluster's mean, until no
// assignment changes. An emptied cluster restarts at the point farthest from its centre.
int lloyd(const std::vector<glm::dvec3>& pts, std::vector<glm::dvec3>& centres, std::vector<std::size_t>& label,
          int max_iterations) {
  label.assign(pts.size(), std::numeric_limits<std::size_t>::max());
  int it = 0;
  for (; it < max_iterations; ++it) {
    bool moved = false;
    for (std::size_t i = 0; i < pts.size(); ++i)
      if (const std::size_t c = nearest(centres, pts[i]); c != label[i]) label[i] = c, moved = true;
    if (!moved) break;
    std::vector<glm::dvec3> sum(centres.size(), glm::dvec3(0.0));
    std::vector<long long> n(centres.size(), 0);
    for (std::size_t i = 0; i < pts.size(); ++i) sum[label[i]] += pts[i], ++n[label[i]];
    for (std::size_t c = 0; c < centres.size(); ++c) {
      if (n[c] > 0) {
        centres[c] = sum[c] / static_cast<double>(n[c]);
        continue;
      }
      std::size_t far = 0;
      for (std::size_t i = 1; i < pts.size(); ++i)
        if (distance2(pts[i], centres[label[i]]) > distance2(pts[far], centres[label[far]])) far = i;
      centres[c] = pts[far];
    }
  }
  return it;
}

// Volume share: 4/3 π r³ = |M| · n_c / n, so the spheres' volumes add up to the solid's.
// Exact for a ball and K = 1; for thin parts (a wing) the ball bulges far out of them.
std::vector<double> volume_share_radii(const std::vector<std::size_t>& label, std::size_t k, double solid_volume) {
  std::vector<double> n(k, 0.0), r(k);
  for (auto c : label) ++n[c];
  for (std::size_t c = 0; c < k; ++c)
    r[c] = std::cbrt(3.0 * solid_volume * n[c] / label.size() / (4.0 * std::numbers::pi));
  return r;
}

// Planform area: π r² = the area of the cluster's points projected on the body's x-y
// plane, counted as occupied cells of a grid of side h = twice the points' mean spacing
// cbrt(V/n). A part t thick puts about 8t/h points in each cell of its planform, so parts
// thicker than h/2 are counted whole, and the cells cut by the outline add about
// perimeter·h/2; that excess about balances what the discs of neighbouring clusters
// overlap (at the spacing itself the shipped sets came out 9–17 % short from below, at
// twice it within −5…+4 %, docs/aircraft.md). A wing of chord c cut into clusters about
// c long gets spheres of radius ≈ c/√π, whose discs cover it as seen from below, where
// the shell rule gives it balls of its thickness.
std::vector<double> planform_area_radii(const std::vector<glm::dvec3>& pts, const std::vector<std::size_t>& label,
                                        std::size_t k, double solid_volume) {
  const double h = 2.0 * std::cbrt(solid_volume / static_cast<double>(pts.size()));
  std::vector<std::vector<std::pair<long long, long long>>> cells(k);
  for (std::size_t i = 0; i < pts.size(); ++i)
    cells[label[i]].push_back({static_cast<long long>(std::floor(pts[i].x / h)),
                               static_cast<long long>(std::floor(pts[i].y / h))});
  std::vector<double> r(k, 0.0);
  for (std::size_t c = 0; c < k; ++c) {
    auto& v = cells[c];
    std::sort(v.begin(), v.end());
    const auto occupied = std::unique(v.begin(), v.end()) - v.begin();
    r[c] = std::sqrt(static_cast<double>(occupied) * h * h / std::numbers::pi);
  }
  return r;
}

// Half-solid shell. Restrict everything to the cluster's Voronoi cell V (the points
// k-means gave it) and minimise its own symmetric difference
//   f(r) = |(B_r ∩ V) \ M| + |(M ∩ V) \ B_r|.
// df/dr = A(r)·(1 − φ(r)) − A(r)·φ(r), with A(r) the area of the sphere of radius r
// inside V and φ(r) the fraction of it inside M: the best r is where φ falls through ½.
// Estimated with the interior points (weight 1) and points outside M drawn at a known
// density (weight = interior density / outside density): f(r) = #in beyond r + w·#out
// within r, minimised by one scan over the sorted distances.
std::vector<double> half_solid_shell_radii(const std::vector<glm::dvec3>& pts, const std::vector<std::size_t>& label,
                                           const std::vector<glm::dvec3>& centres, const std::vector<glm::dvec3>& outside,
                                           double outside_weight) {
  const std::size_t k = centres.size();
  std::vector<std::vector<std::pair<double, double>>> events(k);  // (distance, change of f when r passes it)
  for (std::size_t i = 0; i < pts.size(); ++i)
    events[label[i]].push_back({std::sqrt(distance2(pts[i], centres[label[i]])), -1.0});
  for (const auto& p : outside) {
    const std::size_t c = nearest(centres, p);
    events[c].push_back({std::sqrt(distance2(p, centres[c])), outside_weight});
  }
  std::vector<double> r(k, 0.0);
  for (std::size_t c = 0; c < k; ++c) {
    auto& e = events[c];
    std::sort(e.begin(), e.end());
    double f = 0.0, best_f = 0.0;
    for (std::size_t j = 0; j < e.size(); ++j) {
      f += e[j].second;
      if (f < best_f) {
        best_f = f;
        r[c] = j + 1 < e.size() ? 0.5 * (e[j].first + e[j + 1].first) : e[j].first;
      }
    }
    if (r[c] <= 0.0 && !e.empty()) r[c] = e.front().first;  // a cluster of outside-dominated cells
  }
  return r;
}

}  // namespace

double FitReport::worst_solid_angle_error() const {
  double worst = 0.0;
  for (const auto& v : views) worst = std::max(worst, std::abs(v.relative()));
  return worst;
}

FitErrorSummary FitReport::summary() const {
  FitErrorSummary s;
  s.volume_error = volume.relative;
  s.volume_error_se = volume.relative_se;
  s.volume_samples = volume.samples;
  s.solid_angle_error = worst_solid_angle_error();
  s.solid_angle_rays = views.empty() ? 0 : views.front().rays;
  return s;
}

FitReport measure_fit(const Mesh& mesh, const std::vector<BodySphere>& spheres, const FitOptions& o) {
  const MeshInside inside(mesh);
  FitReport report;
  report.volume = compare_volumes(std::cref(inside), [&](const glm::dvec3& p) { return inside_any(spheres, p); },
                                  bounds(mesh, spheres), o.error_samples, o.seed ^ kErrorStream);
  std::uint64_t stream = o.seed ^ kErrorStream;
  for (const auto& view : standard_viewpoints())
    report.views.push_back(compare_solid_angles(mesh, spheres, view, o.error_rays, ++stream));
  return report;
}

SphereFit fit_spheres(const Mesh& mesh, const FitOptions& o) {
  if (o.k < 1 || static_cast<std::size_t>(o.k) > kMaxSpheres)
    throw FitError("k = " + std::to_string(o.k) + ": the number of spheres must be 1.." + std::to_string(kMaxSpheres));
  if (o.samples < o.k)
    throw FitError(std::to_string(o.samples) + " samples for " + std::to_string(o.k) + " spheres: need at least one per sphere");
  if (o.error_samples < 1 || o.error_rays < 1) throw FitError("the error estimates need at least one sample and one ray");
  check_closed_mesh(mesh, "mesh");
  const MeshInside inside(mesh);
  const Bounds box = bounds(mesh);
  const InteriorSample interior = sample_interior(inside, box, o.samples, o.seed);
  std::mt19937_64 rng(o.seed);
  std::vector<glm::dvec3> centres = seed_centres(interior.points, o.k, rng);
  std::vector<std::size_t> label;
  SphereFit fit;
  fit.iterations = lloyd(interior.points, centres, label, o.max_iterations);

  std::vector<double> radii;
  const double solid_volume = box.volume() * static_cast<double>(interior.points.size()) / interior.attempts;
  if (o.radius_rule == RadiusRule::kVolumeShare) {
    radii = volume_share_radii(label, centres.size(), solid_volume);
  } else if (o.radius_rule == RadiusRule::kPlanformArea) {
    radii = planform_area_radii(interior.points, label, centres.size(), solid_volume);
  } else {
    // Outside points from a second pass, in the box grown by the largest cluster reach
    // (a sphere can stick out of the mesh's box), at density m / |grown box|; interior
    // points came at attempts / |box|, so an outside point weighs the ratio of the two.
    double reach = 0.0;
    for (std::size_t i = 0; i < interior.points.size(); ++i)
      reach = std::max(reach, distance2(interior.points[i], centres[label[i]]));
    const Bounds grown{box.lo - std::sqrt(reach), box.hi + std::sqrt(reach)};
    const long long m = kOutsidePerInside * o.samples;
    std::mt19937_64 out_rng(o.seed ^ kOutsideStream);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<glm::dvec3> outside;
    for (long long i = 0; i < m; ++i) {
      const glm::dvec3 p = grown.lo + glm::dvec3(u(out_rng), u(out_rng), u(out_rng)) * grown.size();
      if (!inside(p)) outside.push_back(p);
    }
    const double outside_weight = (interior.attempts / box.volume()) / (m / grown.volume());
    radii = half_solid_shell_radii(interior.points, label, centres, outside, outside_weight);
  }
  for (std::size_t c = 0; c < centres.size(); ++c)
    if (radii[c] > 0.0) fit.spheres.push_back({centres[c], radii[c]});
  fit.report = measure_fit(mesh, fit.spheres, o);
  return fit;
}

}  // namespace skylit::flight
