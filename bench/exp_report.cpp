// SH exponentiation report (docs/numerics.md §2): HYB vs T2 = expm(M_f)·1
// vs T1 = pointwise exp* vs T0 = projection of the true visibility, for sphere
// scenes (1–400 spheres, random in a cone or coincident), ε, guards, bases,
// thresholds, height-field vectors, and float32 vs double. Usage: exp_report [order]
#include "shading/blockers/sphere_blocker.h"
#include "shading/sh/hyb_table.h"
#include "shading/sh/sh_exp.h"
#include "shading/sh/sh_rotation.h"
#include "shading/sh/wedge.h"
#include "shading/visibility_truth.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

using namespace skylit;
using sh::kPi;
using sh::kSqrt4Pi;

namespace {

int g_order = 4;
const glm::dvec3 kOrigin(0, 0, 0), kUp(0, 0, 1);

double norm(std::span<const double> v) { return std::sqrt(sh::dot(v, v)); }
double diff_norm(const sh::Vec& a, const sh::Vec& b) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(s);
}
double rel(const sh::Vec& x, const sh::Vec& ref) { return diff_norm(x, ref) / norm(ref); }
double abs_err(const sh::Vec& x, const sh::Vec& t0) { return diff_norm(x, t0) / kSqrt4Pi; }
std::string e(double v) {
  char b[32];
  if (!std::isfinite(v)) return "**" + std::string(std::isnan(v) ? "NaN" : "inf") + "**";
  std::snprintf(b, sizeof b, std::abs(v) >= 1e4 || (std::abs(v) < 1e-2 && v != 0) ? "%.1e" : "%.3g", v);
  return b;
}

double uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1p-53; }

struct Scene {
  std::string name;
  std::vector<blockers::Sphere> spheres;
  sh::Vec t0;  // projection of the true visibility (independent of ε)
};

// Centres in a 35° cone about +z, d ∈ [1.5, 6], r/d ∈ [0.15, 0.6] (math-notes §6.3);
// or `count` copies of the first sphere.
Scene make_scene(int count, bool coincident, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  Scene s;
  s.name = std::to_string(count) + (coincident ? " coincident" : "");
  const double cone = 35.0 * kPi / 180;
  for (int i = 0; i < count; ++i) {
    if (coincident && i > 0) {
      s.spheres.push_back(s.spheres.front());
      continue;
    }
    const double cz = 1 - uniform(rng) * (1 - std::cos(cone)), phi = 2 * kPi * uniform(rng);
    const double rz = std::sqrt(1 - cz * cz), d = 1.5 + 4.5 * uniform(rng), ratio = 0.15 + 0.45 * uniform(rng);
    s.spheres.push_back({d * glm::dvec3(rz * std::cos(phi), rz * std::sin(phi), cz), ratio * d});
  }
  shading::Occluders occ;
  for (const auto& sp : s.spheres) {
    const double d = glm::length(sp.centre);
    occ.caps.push_back({sp.centre / d, std::asin(std::min(1.0, sp.radius / d))});
    if (coincident) break;
  }
  s.t0 = shading::project_visibility(g_order, occ, {4096, 16, {}});
  return s;
}

sh::Vec log_vector(const Scene& s, double eps, bool ratio) {
  blockers::BlockerOptions bo;
  bo.epsilon = eps;
  bo.ratio_attenuation = ratio;
  bo.cull_error = 0;
  sh::Vec f(sh::num_coeffs(g_order), 0.0);
  blockers::accumulate_log_visibility(s.spheres, kOrigin, kUp, bo, f);
  return f;
}

sh::HybOptions base_opts(sh::HybBase base, double t = 0.25) {
  sh::HybOptions o;
  o.base = base;
  o.threshold = t;
  o.clamp_output_dc = false;
  o.log_floor_epsilon = 0.0;
  return o;
}

const double kEps[] = {0.001, 0.01, 0.1, 0.2, 0.5};

void single_sphere_table() {
  std::printf("\n### A. Single sphere: HYB vs T2 by base and order (t = 0.25); squaring limit = HYB, t = 1e-3\n\n");
  std::printf("| order | ε | r/d | ‖f̂‖ | k | e(OL,T2) | e(PS2,T2) | e(Taylor1,T2) | e(limit,T2) | e(T2,T1) |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  const glm::dvec3 axis = glm::normalize(glm::dvec3(0.4, -0.2, 0.9));
  for (int order : {2, 4, 6, 8})
    for (double eps : {0.01, 0.1, 0.5})
      for (double s : {0.15, 0.5, 0.9}) {
        sh::Vec f(sh::num_coeffs(order), 0.0);
        sh::add_rotated_zh(sh::cap_zh(order, std::sqrt(1 - s * s)), axis, std::log(eps), f);
        const sh::Vec t2 = sh::exp_product_algebra(f), t1 = sh::exp_pointwise(f, 64, 128);
        sh::HybInfo info;
        const sh::Vec ol = sh::exp_hyb(f, base_opts(sh::HybBase::kOptimalLinear), &info);
        const sh::Vec ps2 = sh::exp_hyb(f, base_opts(sh::HybBase::kTaylor2));
        const sh::Vec ty1 = sh::exp_hyb(f, base_opts(sh::HybBase::kTaylor1));
        const sh::Vec lim = sh::exp_hyb(f, [] {
          auto o = base_opts(sh::HybBase::kTaylor2, 1e-3);
          o.max_squarings = 30;
          return o;
        }());
        std::printf("| %d | %g | %g | %s | %d | %s | %s | %s | %s | %s |\n", order, eps, s, e(info.norm).c_str(),
                    info.squarings, e(rel(ol, t2)).c_str(), e(rel(ps2, t2)).c_str(), e(rel(ty1, t2)).c_str(),
                    e(rel(lim, t2)).c_str(), e(rel(t2, t1)).c_str());
      }
}

void threshold_table(const std::vector<Scene>& scenes) {
  std::printf("\n### B. Threshold t: e(H,T2) (squarings k), ε = 0.1, no guards\n\n");
  const double ts[] = {0.05, 0.125, 0.25, 0.5, 1.0};
  std::printf("| scene | base |");
  for (double t : ts) std::printf(" t=%g |", t);
  std::printf("\n|---|---|");
  for (std::size_t i = 0; i < std::size(ts); ++i) std::printf("---|");
  std::printf("\n");
  for (const Scene& s : scenes) {
    const sh::Vec f = log_vector(s, 0.1, false), t2 = sh::exp_product_algebra(f);
    for (auto [base, name] : {std::pair{sh::HybBase::kOptimalLinear, "OL"}, {sh::HybBase::kTaylor2, "PS2"}}) {
      std::printf("| %s | %s |", s.name.c_str(), name);
      for (double t : ts) {
        sh::HybInfo info;
        const sh::Vec h = sh::exp_hyb(f, base_opts(base, t), &info);
        std::printf(" %s (%d) |", e(rel(h, t2)).c_str(), info.squarings);
      }
      std::printf("\n");
    }
  }
}

void main_table(const std::vector<Scene>& scenes) {
  std::printf("\n### C. All routes on the sphere scenes (no guards, no ratio attenuation; t = 0.25)\n\n");
  std::printf("e(X,Y) = ‖X−Y‖/‖Y‖; a_X = ‖X − T0‖/√(4π); DC = coefficient 0 (√(4π) = 3.545 is fully visible).\n\n");
  std::printf("| spheres | ε | f_0 | ‖f̂‖ | k | e(T2,T1) | e(PS2,T2) | e(OL,T2) | a_T1 | a_T2 | a_PS2 | a_OL | DC T0 / T1 / T2 / PS2 / OL |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Scene& s : scenes)
    for (double eps : kEps) {
      const sh::Vec f = log_vector(s, eps, false);
      const sh::Vec t1 = sh::exp_pointwise(f), t2 = sh::exp_product_algebra(f);
      sh::HybInfo info;
      const sh::Vec ps2 = sh::exp_hyb(f, base_opts(sh::HybBase::kTaylor2), &info);
      const sh::Vec ol = sh::exp_hyb(f, base_opts(sh::HybBase::kOptimalLinear));
      std::printf("| %s | %g | %s | %s | %d | %s | %s | %s | %s | %s | %s | %s | %.3f / %s / %s / %s / %s |\n",
                  s.name.c_str(), eps, e(f[0]).c_str(), e(info.norm).c_str(), info.squarings, e(rel(t2, t1)).c_str(),
                  e(rel(ps2, t2)).c_str(), e(rel(ol, t2)).c_str(), e(abs_err(t1, s.t0)).c_str(),
                  e(abs_err(t2, s.t0)).c_str(), e(abs_err(ps2, s.t0)).c_str(), e(abs_err(ol, s.t0)).c_str(), s.t0[0],
                  e(t1[0]).c_str(), e(t2[0]).c_str(), e(ps2[0]).c_str(), e(ol[0]).c_str());
    }
}

void guard_table(const std::vector<Scene>& scenes) {
  std::printf("\n### D. Guards: a_H = ‖H − T0‖/√(4π) [H DC], HYB PS2, t = 0.25, double\n\n");
  std::printf("floor = clamp f_0 ≥ √(4π)·ln ε (whole vector scaled); DC ≤ √(4π) = output clamp; ratio = LSH r/d.\n\n");
  std::printf("| spheres | ε | T0 DC | none | DC clamp | floor | floor + DC clamp | ratio | ratio + floor + DC clamp | T2 + floor |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Scene& s : scenes)
    for (double eps : kEps) {
      std::printf("| %s | %g | %.3f |", s.name.c_str(), eps, s.t0[0]);
      for (int variant = 0; variant < 6; ++variant) {
        const bool ratio = variant >= 4;
        const sh::Vec f = log_vector(s, eps, ratio);
        sh::HybOptions o = base_opts(sh::HybBase::kTaylor2);
        o.clamp_output_dc = variant == 1 || variant == 3 || variant == 5;
        o.log_floor_epsilon = (variant == 2 || variant == 3 || variant == 5) ? eps : 0.0;
        const sh::Vec h = sh::exp_hyb(f, o);
        std::printf(" %s [%s] |", e(abs_err(h, s.t0)).c_str(), e(h[0]).c_str());
      }
      // T2 of the floor-clamped vector: is the guard's benefit the guard, or HYB?
      sh::Vec f = log_vector(s, eps, false);
      const double floor = kSqrt4Pi * std::log(eps);
      if (f[0] < floor) {
        const double k = floor / f[0];
        for (double& x : f) x *= k;
      }
      const sh::Vec t2 = sh::exp_product_algebra(f);
      std::printf(" %s [%s] |\n", e(abs_err(t2, s.t0)).c_str(), e(t2[0]).c_str());
    }
}

void float_table() {
  std::printf("\n### E. float32 vs double (OL and PS2 bases, t = 0.25, no floor clamp, no DC clamp)\n\n");
  std::printf("| scene | ε | c = f_0/√(4π) | k | base | f32 plain | f32 renormalised | rel. diff. f32 vs f64 |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  struct Case {
    int count;
    double eps;
  };
  for (Case cs : {Case{10, 0.01}, {100, 0.01}, {400, 0.01}, {400, 0.001}, {1000, 0.01}}) {
    Scene s;
    {
      std::mt19937_64 rng(2000 + cs.count);
      const double cone = 35.0 * kPi / 180;
      for (int i = 0; i < cs.count; ++i) {
        const double cz = 1 - uniform(rng) * (1 - std::cos(cone)), phi = 2 * kPi * uniform(rng);
        const double rz = std::sqrt(1 - cz * cz), d = 1.5 + 4.5 * uniform(rng), ratio = 0.15 + 0.45 * uniform(rng);
        s.spheres.push_back({d * glm::dvec3(rz * std::cos(phi), rz * std::sin(phi), cz), ratio * d});
      }
    }
    const sh::Vec f = log_vector(s, cs.eps, false);
    const std::vector<float> ff(f.begin(), f.end());
    for (auto [base, name] : {std::pair{sh::HybBase::kOptimalLinear, "OL"}, {sh::HybBase::kTaylor2, "PS2"}}) {
      sh::HybOptions o = base_opts(base);
      sh::HybInfo info;
      const sh::Vec ref = sh::exp_hyb(f, o, &info);
      std::vector<float> guarded(f.size()), plain(f.size());
      sh::exp_hyb<float>(ff, guarded, o);
      o.renormalise = false;
      sh::exp_hyb<float>(ff, plain, o);
      const auto status = [](const std::vector<float>& v) {
        bool nan = false, inf = false;
        for (float x : v) {
          nan |= std::isnan(x);
          inf |= std::isinf(x);
        }
        return std::string(nan ? "**NaN**" : inf ? "**inf**" : "finite");
      };
      const sh::Vec back(guarded.begin(), guarded.end());
      std::printf("| %d spheres | %g | %.1f | %d | %s | %s | %s | %s |\n", cs.count, cs.eps, f[0] / kSqrt4Pi,
                  info.squarings, name, status(plain).c_str(), status(guarded).c_str(),
                  ref[0] > 0 ? e(rel(back, ref)).c_str() : "(both 0)");
    }
  }
}

void height_field_table() {
  std::printf("\n### F. Height-field log-visibility (W = 32, NLP N = 2n, linear wedges), alone and with 3 spheres\n\n");
  std::printf("Horizon σ(φ) = 25° + 15° cos φ + 8° sin 3φ (lower hemisphere occluded). T0: exact projection.\n\n");
  std::printf("| vector | ε | ‖f̂‖ | k | e(OL,T2) | e(PS2,T2) | e(Taylor1,T2) | e(T2,T1) | a_T2 | a_PS2 | a_OL |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  const auto sigma_of = [](double phi) { return (25 + 15 * std::cos(phi) + 8 * std::sin(3 * phi)) * kPi / 180; };
  const auto& op = sh::wedge_operator(g_order, 2 * g_order, 32, sh::WedgeInterpolation::Linear);
  std::vector<double> sigma(32);
  for (int j = 0; j < 32; ++j) sigma[j] = sigma_of(op.sample_azimuth(j));
  const Scene spheres = [] {
    Scene s;
    s.spheres = {{{1.0, 0.5, 3.0}, 0.9}, {{-0.8, 0.2, 2.5}, 0.6}, {{0.1, -0.9, 4.0}, 1.2}};
    return s;
  }();
  for (bool with_spheres : {false, true}) {
    shading::Occluders occ;
    occ.horizon = sigma_of;
    if (with_spheres)
      for (const auto& sp : spheres.spheres) {
        const double d = glm::length(sp.centre);
        occ.caps.push_back({sp.centre / d, std::asin(sp.radius / d)});
      }
    const sh::Vec t0 = shading::project_visibility(g_order, occ, {4096, 16, {}});
    for (double eps : {0.01, 0.1, 0.2, 0.5}) {
      sh::Vec f = sh::log_visibility_from_horizon(op, sigma, std::log(eps));
      if (with_spheres) {
        const sh::Vec fs = log_vector(spheres, eps, false);
        for (std::size_t i = 0; i < f.size(); ++i) f[i] += fs[i];
      }
      const sh::Vec t1 = sh::exp_pointwise(f), t2 = sh::exp_product_algebra(f);
      sh::HybInfo info;
      const sh::Vec ol = sh::exp_hyb(f, base_opts(sh::HybBase::kOptimalLinear), &info);
      const sh::Vec ps2 = sh::exp_hyb(f, base_opts(sh::HybBase::kTaylor2));
      const sh::Vec ty1 = sh::exp_hyb(f, base_opts(sh::HybBase::kTaylor1));
      std::printf("| %s | %g | %s | %d | %s | %s | %s | %s | %s | %s | %s |\n", with_spheres ? "HF + 3 spheres" : "HF",
                  eps, e(info.norm).c_str(), info.squarings, e(rel(ol, t2)).c_str(), e(rel(ps2, t2)).c_str(),
                  e(rel(ty1, t2)).c_str(), e(rel(t2, t1)).c_str(), e(abs_err(t2, t0)).c_str(),
                  e(abs_err(ps2, t0)).c_str(), e(abs_err(ol, t0)).c_str());
    }
  }
}

void ol_table() {
  std::printf("\n### G. OL table a(m), b(m) as computed at start-up (order %d, ε_train = %g)\n\n", g_order,
              sh::kHybTableEpsilon);
  const auto& t = sh::hyb_table(g_order);
  std::printf("| m | 0.05 | 0.10 | 0.25 | 0.50 | 1.00 | 2.00 |\n|---|---|---|---|---|---|---|\n| (a, b) |");
  for (double m : {0.05, 0.1, 0.25, 0.5, 1.0, 2.0}) {
    const auto [a, b] = t.lookup(m);
    std::printf(" (%.5f, %.5f) |", a, b);
  }
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1) g_order = std::atoi(argv[1]);
  std::printf("## SH exponentiation report (order %d)\n", g_order);
  ol_table();
  single_sphere_table();
  std::vector<Scene> scenes;
  for (int n : {1, 10, 100, 400}) scenes.push_back(make_scene(n, false, 1000 + n));
  for (int n : {10, 100, 400}) scenes.push_back(make_scene(n, true, 1000 + n));
  threshold_table({scenes[0], scenes[1], scenes[2]});
  main_table(scenes);
  guard_table(scenes);
  float_table();
  height_field_table();
  return 0;
}
