#include "shading/visibility_truth.h"

#include "shading/sh/quadrature.h"

#include <algorithm>
#include <cmath>

namespace skylit::shading {
namespace {

constexpr double kHalfPi = sh::kPi / 2;

// Removes [a, b] from a sorted list of disjoint intervals.
void subtract(std::vector<Interval>& vis, double a, double b) {
  std::vector<Interval> out;
  out.reserve(vis.size() + 1);
  for (const auto& [lo, hi] : vis) {
    if (b <= lo || a >= hi) {
      out.push_back({lo, hi});
      continue;
    }
    if (a > lo) out.push_back({lo, a});
    if (b < hi) out.push_back({b, hi});
  }
  vis.swap(out);
}

// Occluded elevations of a cap along the half great circle of azimuth φ:
// ω(e)·a = R cos(e − δ), occluded where it is ≥ cos α.
void subtract_cap(std::vector<Interval>& vis, const Cap& cap, double phi) {
  const double h = cap.axis.x * std::cos(phi) + cap.axis.y * std::sin(phi);
  const double r = std::hypot(h, cap.axis.z);
  const double c = std::cos(std::min(cap.half_angle, sh::kPi));
  if (r <= 0.0) {
    if (c <= 0.0) vis.clear();
    return;
  }
  if (c / r >= 1.0) return;  // the great circle misses the cap
  const double beta = std::acos(std::max(-1.0, c / r));
  const double delta = std::atan2(cap.axis.z, h);
  for (int k = -1; k <= 1; ++k) {
    const double centre = delta + 2.0 * sh::kPi * k;
    subtract(vis, centre - beta, centre + beta);
  }
}

}  // namespace

std::vector<Interval> visible_intervals(const Occluders& occ, double phi) {
  double lo = -kHalfPi;
  if (occ.horizon) lo = std::clamp(occ.horizon(phi), -kHalfPi, kHalfPi);
  std::vector<Interval> vis;
  if (lo < kHalfPi) vis.push_back({lo, kHalfPi});
  for (const auto& cap : occ.caps) subtract_cap(vis, cap, phi);
  return vis;
}

namespace {

// Calls visit(dir, weight) for every quadrature node of the visible set.
template <typename Visit>
void for_each_node(const Occluders& occ, const IntegrationOptions& opt, Visit&& visit) {
  const auto unit = sh::gauss_legendre(opt.gauss_nodes, 0.0, 1.0);
  const double dphi = 2.0 * sh::kPi / opt.azimuths;
  std::vector<double> cuts;
  for (int k = 0; k < opt.azimuths; ++k) {
    const double phi = (k + 0.5) * dphi;
    const double cp = std::cos(phi), sp = std::sin(phi);
    cuts.clear();
    if (opt.clamped_cosine_normal) {
      // n·ω(e) = R cos(e − δ) vanishes at e = δ ± π/2.
      const glm::dvec3& n = *opt.clamped_cosine_normal;
      const double delta = std::atan2(n.z, n.x * cp + n.y * sp);
      for (double e : {delta - kHalfPi, delta + kHalfPi, delta + 3 * kHalfPi, delta - 3 * kHalfPi}) cuts.push_back(e);
    }
    for (const auto& [e0, e1] : visible_intervals(occ, phi)) {
      std::vector<double> pts{e0};
      for (double c : cuts)
        if (c > e0 && c < e1) pts.push_back(c);
      pts.push_back(e1);
      std::sort(pts.begin(), pts.end());
      for (std::size_t s = 0; s + 1 < pts.size(); ++s) {
        const double a = pts[s], len = pts[s + 1] - pts[s];
        for (std::size_t q = 0; q < unit.nodes.size(); ++q) {
          const double e = a + len * unit.nodes[q];
          const double ce = std::cos(e);
          visit(glm::dvec3(ce * cp, ce * sp, std::sin(e)), unit.weights[q] * len * ce * dphi);
        }
      }
    }
  }
}

}  // namespace

double integrate(const Occluders& occ, const std::function<double(const glm::dvec3&)>& g,
                 const IntegrationOptions& opt) {
  double sum = 0.0;
  for_each_node(occ, opt, [&](const glm::dvec3& d, double w) { sum += w * g(d); });
  return sum;
}

sh::Vec project_visibility(int order, const Occluders& occ, const IntegrationOptions& opt) {
  sh::Vec out(sh::num_coeffs(order), 0.0), y(out.size());
  for_each_node(occ, opt, [&](const glm::dvec3& d, double w) {
    sh::eval_basis(order, d, y);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] += w * y[i];
  });
  return out;
}

double cosine_weighted_visibility(const Occluders& occ, const glm::dvec3& normal, int azimuths) {
  IntegrationOptions opt;
  opt.azimuths = azimuths;
  opt.clamped_cosine_normal = normal;
  const glm::dvec3 n = normal;
  return integrate(occ, [n](const glm::dvec3& d) { return std::max(0.0, d.x * n.x + d.y * n.y + d.z * n.z); }, opt) /
         sh::kPi;
}

}  // namespace skylit::shading
