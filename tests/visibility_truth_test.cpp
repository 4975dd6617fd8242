// The ground-truth oracle against closed forms: cap solid angles, the cap ZH
// (math-notes §4), V-valley sky-view (§8) and tilted-plane sky-view.
#include "shading/visibility_truth.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace skylit;
constexpr double kPi = sh::kPi;

TEST(VisibilityTruth, EmptySceneIntegratesTheSphere) {
  shading::Occluders none;
  EXPECT_NEAR(shading::integrate(none, [](const glm::dvec3&) { return 1.0; }, {256, 8, {}}), 4 * kPi, 1e-12);
}

TEST(VisibilityTruth, CapSolidAngleAndZhMatchClosedForm) {
  for (double alpha : {0.1, 0.5236, 1.1198, 2.0}) {
    const glm::dvec3 axis = glm::normalize(glm::dvec3(0.3, -0.5, 0.8));
    shading::Occluders occ{{}, {{axis, alpha}}};
    const double vis = shading::integrate(occ, [](const glm::dvec3&) { return 1.0; }, {4096, 16, {}});
    EXPECT_NEAR(vis, 4 * kPi - 2 * kPi * (1 - std::cos(alpha)), 2e-6) << alpha;
    // A cap about +z: its visibility projects onto ZH; compare with the closed form.
    shading::Occluders zc{{}, {{{0, 0, 1}, alpha}}};
    const auto v = shading::project_visibility(4, zc, {64, 16, {}});
    const double c = std::cos(alpha);
    const double z0 = std::sqrt(kPi) * (1 - c);
    EXPECT_NEAR(v[0], sh::kSqrt4Pi - z0, 1e-12);
    for (int l = 1; l < 4; ++l) {
      const double zl = std::sqrt(kPi * (2 * l + 1)) * (sh::legendre(l - 1, c) - sh::legendre(l + 1, c)) / (2 * l + 1);
      EXPECT_NEAR(v[sh::index(l, 0)], -zl, 1e-12) << "l=" << l;
    }
  }
}

TEST(VisibilityTruth, VValleySkyViewMatchesClosedForm) {
  // Receiver on the crease of an infinite V-valley (walls β1, β2), n = z:
  // σ(φ) = atan(tan β·|cos φ|) per side, SVF = (cos β1 + cos β2)/2.
  for (auto [b1, b2] : {std::pair{30.0, 30.0}, {20.0, 45.0}, {60.0, 60.0}, {10.0, 80.0}}) {
    const double t1 = std::tan(b1 * kPi / 180), t2 = std::tan(b2 * kPi / 180);
    shading::Occluders occ;
    occ.horizon = [=](double phi) {
      const double c = std::cos(phi);
      return std::atan((c >= 0 ? t1 : t2) * std::abs(c));
    };
    const double svf = shading::cosine_weighted_visibility(occ, {0, 0, 1}, 4096);
    EXPECT_NEAR(svf, (std::cos(b1 * kPi / 180) + std::cos(b2 * kPi / 180)) / 2, 1e-7);
  }
}

TEST(VisibilityTruth, TiltedPlaneSkyView) {
  // A plane of slope s under a sky that exists only above the horizontal:
  // the horizon is max(plane, 0), skyview = (1 + cos s)/2.
  for (double s : {0.0, 0.2, 0.7, 1.2}) {
    const glm::dvec3 n(std::sin(s), 0, std::cos(s));
    shading::Occluders occ;
    occ.horizon = [=](double phi) { return std::max(0.0, -std::atan(n.x * std::cos(phi) / n.z)); };
    EXPECT_NEAR(shading::cosine_weighted_visibility(occ, n, 4096), (1 + std::cos(s)) / 2, 1e-7) << s;
  }
}
