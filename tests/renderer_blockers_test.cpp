// Sphere blockers in the CPU reference renderer (shading/blocker_frame.h): closed forms
// (a sphere over a flat plane: the skyview below it and the sun shadow's ellipse), the
// default settings against the truth (--exact: caps exact in elevation per azimuth, the
// disc sampled) for a low aircraft, and hard cases kept finite.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "lighting_test_util.h"
#include "shading/lighting.h"
#include "shading/products.h"
#include "shading/reference_renderer.h"
#include "terrain/synthetic.h"

namespace skylit::shading {
namespace {

using ::skylit::testing::sun_at;  // lighting_test_util.h

constexpr double kPi = std::numbers::pi;

ProductOptions options(bool exact = false) {
  ProductOptions o;
  o.threads = 2;
  o.exact = exact;
  return o;
}

ProductBands render(const terrain::HeightField& f, Product p, const ProductOptions& o,
                    const std::vector<blockers::Sphere>& spheres, std::optional<Lighting> l = std::nullopt) {
  ReferenceRenderer r;
  r.set_field(f);
  r.set_options(o);
  return r.frame(p, {std::move(l), spheres, std::nullopt});
}

// An aircraft-like set of 30 spheres (wing, fuselage, tail) of span `span` metres,
// centred at c, heading east.
std::vector<blockers::Sphere> aircraft(const glm::dvec3& c, double span) {
  std::vector<blockers::Sphere> s;
  const double r_wing = span / 40.0;
  for (int k = 0; k < 20; ++k) s.push_back({c + glm::dvec3(0, (k - 9.5) / 19.0 * (span - 2 * r_wing), 0), r_wing});
  for (int k = 0; k < 8; ++k) s.push_back({c + glm::dvec3((k - 3.5) * span / 20.0, 0, 0), span / 28.0});
  s.push_back({c + glm::dvec3(-0.26 * span, 0, 0.05 * span), span / 30.0});
  s.push_back({c + glm::dvec3(-0.26 * span, 0, 0.10 * span), span / 30.0});
  return s;
}

TEST(RendererBlockers, SkyviewBelowOneSphereOverAPlaneIsOneMinusSinSquared) {
  // A cap of half-angle α about the zenith hides (1/π)∫cap cos θ dω = sin²α of the sky.
  // The plane's extent does not matter (it hides nothing): 9² texels, the sphere over the
  // middle one.
  terrain::HeightField flat(9, 9, 2.0);
  const glm::dvec3 below(4 * 2.0, -4 * 2.0, 0.0);
  for (double ratio : {0.05, 0.2, 0.5}) {
    const double h = 40.0, r = ratio * h;
    const std::vector<blockers::Sphere> s{{below + glm::dvec3(0, 0, h), r}};
    const double closed = 1.0 - ratio * ratio;
    const double exact = render(flat, Product::Skyview, options(true), s).data[4 * 9 + 4];
    EXPECT_NEAR(exact, closed, 1e-4) << ratio;
    // Default: order-4 SH with log ε = log 0.1 inside the sphere.
    const double fast = render(flat, Product::Skyview, options(), s).data[4 * 9 + 4];
    // Default: order-4 SH of the cap, V_T ∗ exp*(log*(V_cap)). A small cap at the zenith
    // truncated to l < 4 weighs Σ (2l+1)/2 ∫₀¹ P_l(μ) μ dμ = 1.0625 against the clamped
    // cosine: 6 % too much of its share sin²α.
    EXPECT_NEAR(fast, closed, 0.065 * ratio * ratio) << ratio;
  }
}

terrain::HeightField hills(int size, double spacing) {
  terrain::SyntheticOptions o;
  o.width = o.height = size;
  o.spacing = spacing;
  o.seed = 5;
  o.relief = 60.0;
  o.feature_size = 400.0;
  return terrain::make_synthetic_terrain(o);
}

struct Errors {
  double rmse = 0.0, max = 0.0;
  double change_rms = 0.0;  // RMS of the truth's change (how much the spheres darken)
  int texels = 0;
};

// Over the texels where the truth's spheres change the product by more than 1e-4: the
// error of `fast` against `exact`.
Errors errors(const ProductBands& fast, const ProductBands& exact, const ProductBands& exact_bare) {
  Errors e;
  double sum = 0.0;
  for (std::size_t t = 0; t < exact.data.size(); ++t) {
    if (std::abs(exact.data[t] - exact_bare.data[t]) <= 1e-4) continue;
    const double d = fast.data[t] - exact.data[t], c = exact.data[t] - exact_bare.data[t];
    sum += d * d;
    e.change_rms += c * c;
    e.max = std::max(e.max, std::abs(d));
    ++e.texels;
  }
  e.rmse = e.texels ? std::sqrt(sum / e.texels) : 0.0;
  e.change_rms = e.texels ? std::sqrt(e.change_rms / e.texels) : 0.0;
  return e;
}

TEST(RendererBlockers, LowAircraftSkyviewMeetsTheTargetAgainstTheTruth) {
  // 30 spheres 150 m above rolling hills, spans of a glider and an airliner: the default
  // settings against --exact over the texels the aircraft changes (the target:
  // RMSE ≤ 0.002, max ≤ 0.02). The terrain's own error is taken out by comparing the
  // changes the spheres make (fast with − fast without vs exact with − exact without).
  const terrain::HeightField f = hills(32, 4.0);
  const glm::dvec3 centre(16 * 4.0, -16 * 4.0, f.at(16, 16) + 150.0);
  ProductBands exact_bare = render(f, Product::Skyview, options(true), {});
  ProductBands fast_bare = render(f, Product::Skyview, options(), {});
  for (double span : {15.0, 35.0}) {
    const auto plane = aircraft(centre, span);
    const ProductBands exact = render(f, Product::Skyview, options(true), plane);
    for (auto comp : {blockers::Composition::kProduct, blockers::Composition::kDelta, blockers::Composition::kLogSum}) {
      ProductOptions o = options();
      o.blockers.composition = comp;
      ProductBands fast = render(f, Product::Skyview, o, plane);
      // The spheres' change alone: shift fast by the terrain's own error.
      for (std::size_t t = 0; t < fast.data.size(); ++t) fast.data[t] += exact_bare.data[t] - fast_bare.data[t];
      const Errors e = errors(fast, exact, exact_bare);
      std::printf("span %.0f m, composition %d: %d texels, change RMS %.5f, RMSE %.5f, max %.5f\n", span,
                  static_cast<int>(comp), e.texels, e.change_rms, e.rmse, e.max);
      if (comp == ProductOptions().blockers.composition) {
        EXPECT_GT(e.texels, 100);
        EXPECT_LE(e.rmse, 0.002) << span;
        EXPECT_LE(e.max, 0.02) << span;
        // What the spheres change beyond the cull budget is captured: order-4 SH spreads a
        // small cap, so a third of its change is misplaced; culled away, all of it would
        // be. A change within the budget may be culled whole (the glider at 150 m: its
        // sky shadow, 2e-4, is a twentieth of an 8-bit code), but by no more than it.
        const double budget = o.blockers.blocker.cull_error;
        if (e.change_rms > budget)
          EXPECT_LE(e.rmse, 0.5 * e.change_rms) << span;
        else
          EXPECT_LE(e.max, budget) << span;
      }
    }
  }
}

TEST(RendererBlockers, SunShadowOfOneSphereIsTheProjectedEllipse) {
  // Over a plane, the shadow of a sphere of radius r under a sun at elevation e is an
  // ellipse with semi-axes r (across) and r/sin e (along the sun's azimuth), centred
  // h/tan e from the point below the sphere, away from the sun.
  terrain::HeightField flat(96, 96, 0.5);
  const double r = 6.0, h = 40.0, e = 40.0 * kPi / 180.0;
  const glm::dvec3 c(70.0, -24.0, h);
  const auto out = render(flat, Product::Shadow, options(), {{c, r}}, sun_at(90.0, 40.0));  // sun in the east
  const double cx = c.x - h / std::tan(e), cy = c.y;
  int wrong = 0, inside = 0;
  for (int j = 0; j < 96; ++j)
    for (int i = 0; i < 96; ++i) {
      const double u = (i * 0.5 - cx) / (r / std::sin(e)), v = (-j * 0.5 - cy) / r;
      const double rho = std::hypot(u, v);
      const double shadow = out.data[j * 96 + i];
      if (rho < 1.0) ++inside;
      // The penumbra reaches (h / sin e)·0.00465 = 0.29 m across (/sin e along) either
      // side of the edge: 4.8 % of each axis.
      if ((rho < 0.94 && shadow > 0.01) || (rho > 1.06 && shadow < 0.99)) ++wrong;
    }
  EXPECT_NEAR(inside, kPi * r * (r / std::sin(e)) / 0.25, 0.02 * inside);
  EXPECT_EQ(wrong, 0);
}

TEST(RendererBlockers, ShadowFootprintMatchesTheTruth) {
  // A 35 m aircraft at 150 m over hills at 1 m texels: texels whose shadow differs from
  // the truth's (terrain exact; disc sampled against the spheres) by more than 0.5 are
  // at most 0.5 % of the footprint (the target).
  const terrain::HeightField f = hills(120, 1.0);
  const glm::dvec3 centre(80.0, -60.0, f.at(60, 60) + 150.0);
  const auto plane = aircraft(centre, 35.0);
  const Lighting sun = sun_at(100.0, 60.0);
  const auto fast = render(f, Product::Shadow, options(), plane, sun);
  const auto exact = render(f, Product::Shadow, options(true), plane, sun);
  const auto bare = render(f, Product::Shadow, options(true), {}, sun);
  int footprint = 0, wrong = 0;
  for (std::size_t t = 0; t < exact.data.size(); ++t) {
    footprint += exact.data[t] < 0.5 && bare.data[t] >= 0.5;
    wrong += std::abs(fast.data[t] - exact.data[t]) > 0.5;
  }
  std::printf("footprint %d texels, misclassified %d\n", footprint, wrong);
  EXPECT_GT(footprint, 40);
  EXPECT_LE(wrong, 0.005 * footprint);
}

TEST(RendererBlockers, TenAircraftMergedFarAwayMatchUnmerged) {
  // Ten airliners over 768 m of hills: a receiver that sees an aircraft's bounding sphere
  // within asin(0.05) takes it as one cap (sphere_groups.h). Against every sphere taken
  // alone, the skyview and the shaded codes barely move, while most caps are merged.
  const terrain::HeightField f = hills(96, 8.0);
  std::vector<blockers::Sphere> planes;
  for (int k = 0; k < 10; ++k) {
    const int i = 10 + 8 * k, j = 20 + 6 * (k % 5);
    const auto a = aircraft({i * 8.0, -j * 8.0, f.at(i, j) + 150.0}, 35.0);
    planes.insert(planes.end(), a.begin(), a.end());
  }
  ProductOptions merged = options(), alone = options();
  alone.blockers.merge_sin = 0.0;
  const ProductBands bare = render(f, Product::Skyview, merged, {});
  const ProductBands m = render(f, Product::Skyview, merged, planes), a = render(f, Product::Skyview, alone, planes);
  double worst = 0.0, change = 0.0;
  for (std::size_t t = 0; t < m.data.size(); ++t) {
    worst = std::max(worst, std::abs(static_cast<double>(m.data[t]) - a.data[t]));
    change = std::max(change, std::abs(static_cast<double>(a.data[t]) - bare.data[t]));
  }
  std::printf("ten aircraft: merged against alone max %.2g (largest change %.3g)\n", worst, change);
  EXPECT_GT(change, 5e-3);
  EXPECT_LE(worst, 1e-4);  // a tenth of the cull budget
}

TEST(RendererBlockers, NoMergedCapReachesAcrossTheHorizon) {
  // An airliner behind a 40 m ridge, as high as the ridge's top seen from the plain in
  // front: a cap merged across the horizon would darken the sky by the part the ridge
  // already hides. Nodes across the horizon take their members, so even wide merge sines
  // stay within the merging's own small error of taking every sphere alone. No cull.
  terrain::HeightField f(96, 96, 4.0);
  for (int j = 0; j < f.height; ++j)
    for (int i = 44; i < 48; ++i) f.at(i, j) = 40.0f;
  f.mark_all_dirty();
  const auto plane = aircraft({55 * 4.0, -48 * 4.0, 80.0}, 35.0);
  ProductOptions alone = options();
  alone.blockers.merge_sin = 0.0;
  alone.blockers.blocker.cull_error = 0.0;
  const ProductBands bare = render(f, Product::Skyview, alone, {}), a = render(f, Product::Skyview, alone, plane);
  for (double merge_sin : {0.2, 0.4}) {
    ProductOptions merged = alone;
    merged.blockers.merge_sin = merge_sin;
    const ProductBands m = render(f, Product::Skyview, merged, plane);
    double worst = 0.0, change = 0.0;
    for (int j = 0; j < f.height; ++j)
      for (int i = 0; i < 40; ++i) {  // the plain in front of the ridge
        const std::size_t t = static_cast<std::size_t>(j) * f.width + i;
        worst = std::max(worst, std::abs(static_cast<double>(m.data[t]) - a.data[t]));
        change = std::max(change, std::abs(static_cast<double>(a.data[t]) - bare.data[t]));
      }
    std::printf("behind a ridge, merge sine %.2f: merged against alone max %.2g (largest change %.3g)\n", merge_sin,
                worst, change);
    EXPECT_GT(change, 2e-4);
    EXPECT_LE(worst, 0.02 * change);
  }
}

TEST(RendererBlockers, EachReceiverDropsNoMoreThanTheBudget) {
  // Ten airliners over 768 m of hills: what the cull drops at a texel (whole aircraft, the
  // smallest bounds first; receiver_budget.h) moves its skyview by at most the budget,
  // against culling nothing, though every aircraft is listed over most of the field.
  const terrain::HeightField f = hills(96, 8.0);
  std::vector<blockers::Sphere> planes;
  for (int k = 0; k < 10; ++k) {
    const int i = 8 + 9 * k, j = 10 + 19 * (k % 4);
    const auto a = aircraft({i * 8.0, -j * 8.0, f.at(i, j) + 150.0 + 20.0 * k}, 35.0);
    planes.insert(planes.end(), a.begin(), a.end());
  }
  ProductOptions culled = options(), all = options();
  all.blockers.blocker.cull_error = 0.0;
  const ProductBands bare = render(f, Product::Skyview, culled, {});
  const ProductBands c = render(f, Product::Skyview, culled, planes), a = render(f, Product::Skyview, all, planes);
  double worst = 0.0;
  int dropped_some = 0, dropped_all = 0;
  for (std::size_t t = 0; t < c.data.size(); ++t) {
    worst = std::max(worst, std::abs(static_cast<double>(c.data[t]) - a.data[t]));
    dropped_some += c.data[t] != a.data[t];
    dropped_all += c.data[t] == bare.data[t] && a.data[t] != bare.data[t];
  }
  std::printf("ten aircraft: culled against all max %.2g (budget %.0e); of %zu texels %d drop some aircraft, %d all\n",
              worst, culled.blockers.blocker.cull_error, c.data.size(), dropped_some, dropped_all);
  EXPECT_LE(worst, culled.blockers.blocker.cull_error);
  EXPECT_GT(dropped_some, static_cast<int>(c.data.size()) / 2);
}

TEST(RendererBlockers, HardCasesStayFiniteAndBounded) {
  // 400 coincident spheres, spheres in and below the ground, a 1 mm sphere, an aircraft
  // at 10 km, ε (the log* clip) from 1e-3 to 0.5: every product finite, in range, and
  // within a bound of the truth. The bound is loose: 400 coincident spheres sum 400
  // logs where the union is one cap, and exp* of that rings (skyview error 0.24 where
  // receivers take them unmerged; a merged cap is clamped to the node's bound, without
  // which merging at 0.1 made it 0.83).
  const terrain::HeightField f = hills(16, 4.0);
  const double ground = f.at(8, 8);
  const glm::dvec3 above(32.0, -32.0, ground);
  const blockers::Sphere coincident{above + glm::dvec3(0, 0, 30), 5.0};
  std::vector<std::vector<blockers::Sphere>> cases = {
      std::vector<blockers::Sphere>(400, coincident),
      {{above + glm::dvec3(0, 0, 2), 6.0}, {above + glm::dvec3(20, 0, -30), 10.0}},
      {{above + glm::dvec3(0, 0, 20), 0.001}},
      aircraft(above + glm::dvec3(0, 0, 10000), 35.0)};
  const Lighting sun = sun_at(200.0, 50.0);
  for (std::size_t c = 0; c < cases.size(); ++c) {
    // The truth's adaptive quadrature is slow on many spheres and on tiny caps, so:
    // 400 coincident spheres hide what one of them hides; and a sphere of radius r whose
    // centre is D away is a cap of sin α = r/D, which hides at most its solid angle over
    // π, 2(1 − cos α) ≤ 2 sin²α, of the cosine-weighted sky. Where that sums below 1e-5,
    // the truth is the bare terrain's.
    double tiny_share = 0.0;
    for (const auto& s : cases[c]) {
      double d = 1e300;
      for (int j = 0; j < f.height; ++j)
        for (int i = 0; i < f.width; ++i)
          d = std::min(d, glm::length(s.centre - glm::dvec3(i * f.dx(j), -j * f.dy, f.at(i, j))));
      tiny_share += d > s.radius ? 2.0 * (s.radius / d) * (s.radius / d) : 1.0;
    }
    std::vector<blockers::Sphere> truth_spheres = cases[c];
    if (c == 0) truth_spheres = {coincident};
    if (tiny_share < 1e-5) truth_spheres.clear();
    const auto exact = render(f, Product::Skyview, options(true), truth_spheres);
    for (double eps : {1e-3, 0.1, 0.5}) {
      ProductOptions o = options();
      o.blockers.blocker.log_clip = eps;
      const auto sky = render(f, Product::Skyview, o, cases[c]);
      const auto irr = render(f, Product::Irradiance, o, cases[c], sun);
      double worst = 0.0;
      for (std::size_t t = 0; t < sky.data.size(); ++t) {
        ASSERT_TRUE(std::isfinite(sky.data[t]) && std::isfinite(irr.data[t])) << c << " " << eps;
        EXPECT_GE(irr.data[t], 0.0f);
        worst = std::max(worst, std::abs(static_cast<double>(sky.data[t]) - exact.data[t]));
      }
      std::printf("case %zu eps %.3f: worst skyview error %.4f\n", c, eps, worst);
      EXPECT_LT(worst, 0.25 + eps) << c << " " << eps;  // inside a sphere: up to the clip
    }
  }
}

}  // namespace
}  // namespace skylit::shading
