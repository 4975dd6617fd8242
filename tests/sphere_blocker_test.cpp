// Sphere blockers against independent derivations: the cap ZH closed form vs the
// ground-truth projection (exact in elevation) and vs a quadrature in the cap's
// own frame for rotated caps; math-notes §4 table T1; culling; accumulation.
#include "shading/blockers/sphere_blocker.h"
#include "shading/sh/quadrature.h"
#include "shading/sh/sh_rotation.h"
#include "shading/visibility_truth.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "shading/sh/sh_exp_reference.h"

#include <cmath>
#include <vector>

using namespace skylit;
using sh::kPi;

namespace {

double norm(const sh::Vec& v) { return std::sqrt(sh::dot(v, v)); }

double rel_diff(const sh::Vec& a, const sh::Vec& b) {
  sh::Vec d(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) d[i] = a[i] - b[i];
  return norm(d) / std::max(norm(b), 1e-300);
}

// ZH of a cap about +z as a full SH vector (m = 0 entries only).
sh::Vec zh_to_sh(const sh::Vec& zh) {
  const int n = static_cast<int>(zh.size());
  sh::Vec v(sh::num_coeffs(n), 0.0);
  for (int l = 0; l < n; ++l) v[sh::index(l, 0)] = zh[l];
  return v;
}

// ∫_cap y_i dω integrated in the cap's own frame (GL in cos θ' on [cos α, 1] ×
// uniform φ'): exact for band-limited y_i, and independent of the ZH rotation.
sh::Vec cap_projection_in_own_frame(int order, const glm::dvec3& axis, double alpha) {
  const glm::dvec3 helper = std::abs(axis.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  const glm::dvec3 u = glm::normalize(glm::cross(helper, axis)), w = glm::cross(axis, u);
  const auto gl = sh::gauss_legendre(2 * order + 4, std::cos(alpha), 1.0);
  const int nphi = 2 * order + 3;
  sh::Vec out(sh::num_coeffs(order), 0.0), y(out.size());
  for (std::size_t q = 0; q < gl.nodes.size(); ++q) {
    const double z = gl.nodes[q], r = std::sqrt(1 - z * z);
    for (int j = 0; j < nphi; ++j) {
      const double phi = 2 * kPi * j / nphi;
      const glm::dvec3 d = z * axis + r * std::cos(phi) * u + r * std::sin(phi) * w;
      sh::eval_basis(order, d, y);
      for (std::size_t i = 0; i < y.size(); ++i) out[i] += gl.weights[q] * (2 * kPi / nphi) * y[i];
    }
  }
  return out;
}

}  // namespace

TEST(SphereBlocker, CapAboutZMatchesGroundTruthProjection) {
  for (int order : {1, 2, 3, 4, 6, 8})
    for (double alpha : {0.02, 0.3, 0.7853981633974483, 1.2, kPi / 2}) {
      shading::Occluders occ{{}, {{{0, 0, 1}, alpha}}};
      const sh::Vec t0 = shading::project_visibility(order, occ, {32, 24, {}});
      const sh::Vec vis = zh_to_sh(sh::cap_visibility_zh(order, std::cos(alpha)));
      EXPECT_LT(rel_diff(vis, t0), 1e-9) << "order " << order << " alpha " << alpha;
      // Occlusion = 1 − visibility, compared relative to its own norm.
      sh::Vec occl = sh::constant_one(order);
      for (std::size_t i = 0; i < occl.size(); ++i) occl[i] -= t0[i];
      EXPECT_LT(rel_diff(zh_to_sh(sh::cap_zh(order, std::cos(alpha))), occl), 1e-9) << order << " " << alpha;
    }
}

TEST(SphereBlocker, OrderFourSFormMatchesLegendreForm) {
  // math-notes §4 written in s = r/d: an independent algebraic form.
  for (double s : {0.05, 0.3, 0.5, 0.8, 0.99, 1.0}) {
    const double c = std::sqrt(1 - s * s);
    const sh::Vec z = sh::cap_zh(4, blockers::sphere_cap_cos(s, 1.0));
    EXPECT_NEAR(z[0], std::sqrt(kPi) * (1 - c), 1e-14);
    EXPECT_NEAR(z[1], std::sqrt(3 * kPi) / 2 * s * s, 1e-14);
    EXPECT_NEAR(z[2], std::sqrt(5 * kPi) / 2 * s * s * c, 1e-14);
    EXPECT_NEAR(z[3], std::sqrt(7 * kPi) / 8 * s * s * (4 - 5 * s * s), 1e-14);
  }
}

TEST(SphereBlocker, MathNotesTableT1) {
  struct Row {
    double s, cap[4], log_zh[4], vis[4];
  };
  const Row rows[] = {
      {0.1, {0.008885, 0.015350, 0.019717, 0.023154}, {-0.020457, -0.035344, -0.045401, -0.053315},
       {3.536023, -0.015350, -0.019717, -0.023154}},
      {0.5, {0.237464, 0.383748, 0.429043, 0.403002}, {-0.546781, -0.883611, -0.987907, -0.927945},
       {3.307444, -0.383748, -0.429043, -0.403002}},
      {0.9, {0.999859, 1.243342, 0.699668, -0.023740}, {-2.302261, -2.862901, -1.611044, 0.054664},
       {2.545049, -1.243342, -0.699668, 0.023740}},
  };
  for (const Row& r : rows) {
    const double c = blockers::sphere_cap_cos(r.s, 1.0);
    EXPECT_NEAR(std::acos(c), std::asin(r.s), 1e-12);
    const sh::Vec cap = sh::cap_zh(4, c), lg = sh::cap_log_visibility_zh(4, c, 0.1), vis = sh::cap_visibility_zh(4, c);
    for (int l = 0; l < 4; ++l) {
      EXPECT_NEAR(cap[l], r.cap[l], 1e-6) << r.s << " l=" << l;
      EXPECT_NEAR(lg[l], r.log_zh[l], 1e-6) << r.s << " l=" << l;
      EXPECT_NEAR(vis[l], r.vis[l], 1e-6) << r.s << " l=" << l;
    }
  }
}

TEST(SphereBlocker, RotatedCapMatchesOwnFrameQuadratureAndTruth) {
  const glm::dvec3 axes[] = {glm::normalize(glm::dvec3(0.3, -0.5, 0.8)), glm::normalize(glm::dvec3(-0.7, 0.2, 0.1)),
                             glm::dvec3(0, 0, -1)};
  for (int order : {2, 4, 8})
    for (const auto& axis : axes)
      for (double alpha : {0.1, 0.6, 1.4}) {
        const sh::Vec rotated = sh::rotate_zh(sh::cap_zh(order, std::cos(alpha)), axis);
        EXPECT_LT(rel_diff(rotated, cap_projection_in_own_frame(order, axis, alpha)), 1e-9)
            << order << " " << alpha;
      }
  // And against the ground truth (midpoint in φ: converges slowly, hence the tolerance).
  const glm::dvec3 axis = axes[0];
  const double alpha = 0.6;
  shading::Occluders occ{{}, {{axis, alpha}}};
  const sh::Vec t0 = shading::project_visibility(4, occ, {2048, 16, {}});
  sh::Vec vis = sh::constant_one(4);
  sh::add_rotated_zh(sh::cap_zh(4, std::cos(alpha)), axis, -1.0, vis);
  EXPECT_LT(rel_diff(vis, t0), 1e-5);
}

TEST(SphereBlocker, CullsBelowTangentPlaneOnly) {
  const glm::dvec3 p(1, 2, 3), n = glm::normalize(glm::dvec3(0.2, -0.1, 1.0));
  const blockers::BlockerOptions opt;
  const double r = 0.5;
  // Centre below the plane by more than r: culled. By less: it pokes above, kept.
  EXPECT_EQ(blockers::classify_sphere({p - (r + 1e-6) * n, r}, p, n, 4, opt), blockers::Cull::kBelowTangentPlane);
  const glm::dvec3 tangent = glm::normalize(glm::cross(n, glm::dvec3(0, 1, 0)));
  EXPECT_EQ(blockers::classify_sphere({p - (r + 1e-9) * n + 3.0 * tangent, r}, p, n, 4, opt), blockers::Cull::kBelowTangentPlane);
  EXPECT_EQ(blockers::classify_sphere({p - 0.5 * r * n + 0.1 * glm::dvec3(1, 0, 0), r}, p, n, 4, opt), blockers::Cull::kKeep);
  EXPECT_EQ(blockers::classify_sphere({p + 2.0 * n, r}, p, n, 4, opt), blockers::Cull::kKeep);
}

TEST(SphereBlocker, SizeCullingHonoursItsErrorBound) {
  const blockers::BlockerOptions opt;  // the default cull_error
  for (int order : {2, 4, 8}) {
    const double omega_min = blockers::min_cap_solid_angle(order, opt);
    // Sphere at distance 1 whose cap has exactly omega_min: c = 1 − Ω/(2π), r = sin α.
    const double c = 1 - omega_min / (2 * kPi), r = std::sqrt(1 - c * c);
    const glm::dvec3 p(0, 0, 0), n(0, 0, 1), dir = glm::normalize(glm::dvec3(0.3, 0.1, 1));
    EXPECT_EQ(blockers::classify_sphere({dir, r * 0.999}, p, n, order, opt), blockers::Cull::kTooSmall);
    EXPECT_EQ(blockers::classify_sphere({dir, r * 1.001}, p, n, order, opt), blockers::Cull::kKeep);
    // The visibility change of a dropped sphere (exact cap projection) is within the target.
    const sh::Vec dv = cap_projection_in_own_frame(order, dir, std::asin(r));
    EXPECT_LE(norm(dv) / sh::kSqrt4Pi, opt.cull_error * 1.001) << order;
    EXPECT_GT(norm(dv) / sh::kSqrt4Pi, opt.cull_error * 0.3) << "bound should not be loose by much";
  }
}

TEST(SphereBlocker, AccumulationMatchesProjectedLogVisibility) {
  // Log-visibility of spheres = Σ_i log ε_i·[ω ∈ cap_i]; its projection is
  // Σ_i log ε_i·(1 − P[V_i]) with P[V_i] the ground-truth projection of one cap.
  const glm::dvec3 p(0, 0, 0), n(0, 0, 1);
  const std::vector<blockers::Sphere> spheres = {{{1, 0.5, 2}, 0.6}, {{-0.5, 0.4, 1.2}, 0.3}, {{0.2, -1, 3}, 1.0},
                                           {{0, 0, -3}, 1.0} /* below the plane */};
  for (bool ratio : {false, true}) {
    blockers::BlockerOptions opt;
    opt.log = blockers::CapLog::kPointwise;  // LSH eq. 26
    opt.epsilon = 0.05;
    opt.ratio_attenuation = ratio;
    sh::Vec acc(16, 0.0);
    EXPECT_EQ(blockers::accumulate_log_visibility(spheres, p, n, opt, acc), 3);
    sh::Vec ref(16, 0.0);
    for (std::size_t s = 0; s < 3; ++s) {
      const glm::dvec3 to_c = spheres[s].centre - p;
      const double d = glm::length(to_c), alpha = std::asin(spheres[s].radius / d);
      const double w = std::log(opt.epsilon) * (ratio ? spheres[s].radius / d : 1.0);
      const sh::Vec v = shading::project_visibility(4, {{}, {{to_c / d, alpha}}}, {2048, 12, {}});
      for (int i = 0; i < 16; ++i) ref[i] += w * ((i == 0 ? sh::kSqrt4Pi : 0.0) - v[i]);
    }
    EXPECT_LT(rel_diff(acc, ref), 1e-4) << ratio;  // midpoint rule in φ of the truth
  }
}

TEST(SphereBlocker, ProductAlgebraLogInvertsTheExponential) {
  // The default cap log is log*(V_cap): the product-algebra exponential (T2) of it gives
  // back the cap's visibility ZH (√(4π) − z_0, −z_1, …) from the closed form, for small
  // and large caps (the table's linear interpolation in s² is the error) until the
  // band-limited visibility of a very large cap has eigenvalues below the clip (r/d = 0.85:
  // 4 %).
  const glm::dvec3 p(0, 0, 0), n(0, 0, 1);
  for (double s : {0.05, 0.3, 0.6, 0.85}) {
    const std::vector<blockers::Sphere> one{{{0, 0, 1.0}, s}};
    sh::Vec f(16, 0.0);
    ASSERT_EQ(blockers::accumulate_log_visibility(one, p, n, blockers::BlockerOptions{}, f), 1);
    const sh::Vec v = sh::exp_product_algebra(f);
    const sh::Vec cap = sh::cap_zh(4, std::sqrt(1 - s * s));
    sh::Vec want(16, 0.0);
    for (int l = 0; l < 4; ++l) want[sh::index(l, 0)] = (l == 0 ? sh::kSqrt4Pi : 0.0) - cap[l];
    EXPECT_LT(rel_diff(v, want), s < 0.8 ? 1e-4 : 0.05) << s;
  }
}

TEST(SphereBlocker, ReceiverInsideSphereSeesAHemisphere) {
  const glm::dvec3 p(0, 0, 0), n(0, 0, 1);
  blockers::BlockerOptions opt;
  opt.log = blockers::CapLog::kPointwise;
  sh::Vec inside(16, 0.0), at_centre(16, 0.0);
  blockers::accumulate_log_visibility(std::vector<blockers::Sphere>{{{0.5, 0, 0}, 1.0}}, p, n, opt, inside);
  blockers::accumulate_log_visibility(std::vector<blockers::Sphere>{{{0, 0, 0}, 1.0}}, p, n, opt, at_centre);
  const sh::Vec hemi = sh::cap_zh(4, 0.0);
  const sh::Vec ref_x = sh::rotate_zh(hemi, {1, 0, 0}), ref_z = sh::rotate_zh(hemi, {0, 0, 1});
  for (int i = 0; i < 16; ++i) {
    EXPECT_NEAR(inside[i], std::log(0.1) * ref_x[i], 1e-12);
    EXPECT_NEAR(at_centre[i], std::log(0.1) * ref_z[i], 1e-12);
  }
  EXPECT_EQ(blockers::sphere_cap_cos(0.0, 0.0), 1.0);  // a zero sphere occludes nothing
}
