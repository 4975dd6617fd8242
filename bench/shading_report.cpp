// Shading-mode accuracy report (docs/numerics.md §3): the outgoing radiance
// ∫ L·V·g_r dω of each mode of shading_modes.h against brute force
// (visibility_truth::integrate, exact in elevation per azimuth), for Lambert and
// Phong r = 4, 16, with no occluder, a height-field horizon, and 1, 3, 10 spheres
// over flat ground. Prints markdown. Usage: shading_report [azimuths]
#include "shading/blockers/sphere_blocker.h"
#include "shading/brdf.h"
#include "shading/sh/nlp.h"
#include "shading/sh/quadrature.h"
#include "shading/sh/sh_exp.h"
#include "shading/sh/sh_product.h"
#include "shading/sh/sh_rotation.h"
#include "shading/sh/wedge.h"
#include "shading/shading_modes.h"
#include "shading/sky/sky_cie.h"
#include "shading/sky/sky_sh.h"
#include "shading/sky_brdf_table.h"
#include "shading/visibility_truth.h"

#include <glm/geometric.hpp>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

using namespace skylit;
using shading::Brdf;
using shading::BrdfKind;

namespace {

constexpr int kOrder = 4;
constexpr double kPi = sh::kPi;
const double kEpsilons[] = {0.01, 0.05, 0.1, 0.2};
int g_azimuths = 2048;

// The smooth non-symmetric horizon of math-notes §3 (5° to 50°).
double hf_horizon(double phi) {
  return 0.35 + 0.3 * std::cos(phi - 0.4) + 0.15 * std::sin(2 * phi + 1) + 0.1 * std::cos(3 * phi);
}

// Deterministic spheres (portable LCG): centres in a 25° cone about elevation
// 60°, azimuth 40° (toward the test sun), d ∈ [1.5, 6], r/d ∈ [0.15, 0.6].
std::vector<blockers::Sphere> make_spheres(int count) {
  std::uint64_t state = 0x9e3779b97f4a7c15ULL;
  auto uniform = [&state]() {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  };
  const glm::dvec3 axis = sh::direction(kPi / 2 - 60 * kPi / 180, 40 * kPi / 180);
  const glm::dvec3 e1 = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), axis)), e2 = glm::cross(axis, e1);
  std::vector<blockers::Sphere> out;
  for (int k = 0; k < count; ++k) {
    const double cos_t = 1 - uniform() * (1 - std::cos(25 * kPi / 180)), phi = 2 * kPi * uniform();
    const double sin_t = std::sqrt(1 - cos_t * cos_t);
    const glm::dvec3 dir = cos_t * axis + sin_t * (std::cos(phi) * e1 + std::sin(phi) * e2);
    const double d = 1.5 + 4.5 * uniform(), s = 0.15 + 0.45 * uniform();
    out.push_back({d * dir, s * d});
  }
  return out;
}

struct Scene {
  std::string name;
  shading::Occluders occ;                 // the true binary visibility
  std::vector<blockers::Sphere> spheres;  // over flat ground (σ = 0) when non-empty
  bool height_field = false;
};

// Plain visibility the pipeline would produce: wedge assembly (W = 32, N = 8,
// linear) for the height field; ground ⊗ HYB(Σ sphere log) for blockers.
sh::Vec pipeline_visibility(const Scene& s) {
  if (s.height_field) {
    const auto& op = sh::wedge_operator(kOrder, 8, 32, sh::WedgeInterpolation::Linear);
    std::vector<double> sigma(32);
    for (int j = 0; j < 32; ++j) sigma[j] = hf_horizon(op.sample_azimuth(j));
    return sh::visibility_from_horizon(op, sigma);
  }
  if (s.spheres.empty()) return sh::constant_one(kOrder);
  sh::Vec logv(sh::num_coeffs(kOrder), 0.0);
  blockers::BlockerOptions opt;
  opt.epsilon = 0.1;
  blockers::accumulate_log_visibility(s.spheres, {0, 0, 0}, {0, 0, 1}, opt, logv);
  const sh::Vec blockers = sh::exp_hyb(logv);
  // Ground: the cap {e > 0} as a ZH (√(2π)·NLP visibility at σ = 0), exact.
  const sh::Vec slice = sh::nlp_visibility(kOrder, 0.0);
  sh::Vec ground_zh(kOrder);
  for (int l = 0; l < kOrder; ++l) ground_zh[l] = std::sqrt(2 * kPi) * slice[l];
  return sh::triple_product(kOrder).product(sh::rotate_zh(ground_zh, {0, 0, 1}), blockers);
}

// Log-visibility with floor ε for the log-BRDF mode: log ε·occlusion.
sh::Vec log_visibility(const Scene& s, double eps) {
  sh::Vec logv(sh::num_coeffs(kOrder), 0.0);
  if (!s.height_field && s.spheres.empty()) return logv;
  const auto& op = sh::wedge_operator(kOrder, 8, 32, sh::WedgeInterpolation::Linear);
  std::vector<double> sigma(32, 0.0);
  if (s.height_field)
    for (int j = 0; j < 32; ++j) sigma[j] = hf_horizon(op.sample_azimuth(j));
  logv = sh::log_visibility_from_horizon(op, sigma, std::log(eps));
  blockers::BlockerOptions opt;
  opt.epsilon = eps;
  blockers::accumulate_log_visibility(s.spheres, {0, 0, 0}, {0, 0, 1}, opt, logv);
  return logv;
}

std::string pct(double value, double ref) {
  char buf[32];
  const double e = 100.0 * (value - ref) / ref;
  if (!std::isfinite(e)) return "nan";
  if (std::abs(e) < 0.01)
    std::snprintf(buf, sizeof buf, "%+.3f%%", e);
  else if (std::abs(e) < 10)
    std::snprintf(buf, sizeof buf, "%+.2f%%", e);
  else
    std::snprintf(buf, sizeof buf, "%+.0f%%", e);
  return buf;
}

// Appends "| cell " (the row is closed by " |").
void add_cell(std::string& row, const std::string& cell) {
  row += row.empty() ? "| " : " | ";
  row += cell;
}

struct Sky {
  shading::Radiance full;  // L
  sh::Vec sh;              // L̃
  bool zero_below_horizon;
};

struct Case {
  std::string name;
  Brdf brdf;
  glm::dvec3 axis;
};

// Worst |error| as a fraction of the unoccluded radiance, per mode column.
struct Worst {
  std::vector<std::string> names;
  std::vector<double> err;
  void add(std::size_t k, const std::string& name, double value, double ref, double open) {
    if (names.size() <= k) {
      names.resize(k + 1);
      err.resize(k + 1, 0.0);
    }
    names[k] = name;
    err[k] = std::max(err[k], std::abs(value - ref) / open);
  }
};

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1) g_azimuths = std::atoi(argv[1]);
  const auto t_start = std::chrono::steady_clock::now();

  std::vector<Sky> skies;
  {
    const shading::Radiance L = shading::test_sky_radiance;
    skies.push_back({L, sh::project_smooth(kOrder, L, 64, 128), false});
    auto cie = std::make_shared<sky::CieSky>(12, shading::test_sky_sun(), sky::Rgb(1.0));
    const shading::Radiance Lc = [cie](const glm::dvec3& d) { return cie->relative_luminance(d); };
    skies.push_back({Lc, sh::project(kOrder, sky::upper_hemisphere_rule(256, 512), Lc), true});
  }

  std::vector<Scene> scenes;
  scenes.push_back({"no occluder", {}, {}, false});
  {
    Scene hf{"HF horizon", {}, {}, true};
    hf.occ.horizon = hf_horizon;
    scenes.push_back(hf);
  }
  for (int n : {1, 3, 10}) {
    Scene s{std::to_string(n) + (n == 1 ? " sphere" : " spheres"), {}, make_spheres(n), false};
    s.occ.horizon = [](double) { return 0.0; };
    for (const auto& sp : s.spheres)
      s.occ.caps.push_back({glm::normalize(sp.centre), std::asin(std::min(1.0, sp.radius / glm::length(sp.centre)))});
    scenes.push_back(s);
  }

  const glm::dvec3 tilted_normal = sh::direction(kPi / 2 - 70 * kPi / 180, 200 * kPi / 180);
  const glm::dvec3 mirror = sh::direction(kPi / 2 - 55 * kPi / 180, 60 * kPi / 180);
  const Case cases[] = {{"Lambert", Brdf{}, tilted_normal},
                        {"Phong r=4", Brdf{BrdfKind::Phong, 4.0}, mirror},
                        {"Phong r=16", Brdf{BrdfKind::Phong, 16.0}, mirror}};
  const auto& gamma = sh::triple_product(kOrder);

  std::string table_a, table_b;
  Worst worst_test, worst_cie, worst_pipe;
  for (const Case& c : cases) {
    const shading::AxisGrid grid =
        c.brdf.kind == BrdfKind::Lambert ? shading::AxisGrid::hemisphere() : shading::AxisGrid::sphere();
    const double r = c.brdf.lobe_exponent();
    const glm::dvec3 a = c.axis;
    const sh::Vec lobe = shading::brdf_zh(kOrder, c.brdf);
    std::vector<std::unique_ptr<shading::SkyBrdfTable>> tables;
    for (const Sky& sky : skies) tables.push_back(std::make_unique<shading::SkyBrdfTable>(kOrder, r, sky.full, grid));
    const sh::Vec test_sh = skies[0].sh;
    const shading::Radiance test_bl = [&test_sh](const glm::dvec3& d) { return sh::reconstruct(test_sh, d); };
    const shading::SkyBrdfTable table_bl(kOrder, r, test_bl, grid);

    auto reference = [&](const Scene& s, const shading::Radiance& L, bool cut) {
      shading::Occluders occ = s.occ;
      if (cut && !occ.horizon) occ.horizon = [](double) { return 0.0; };  // L = 0 below: same integral, no jump
      shading::IntegrationOptions io;
      io.azimuths = g_azimuths;
      io.clamped_cosine_normal = a;
      return shading::integrate(
          occ, [&](const glm::dvec3& d) { return L(d) * shading::lobe_profile(r, glm::dot(d, a)); }, io);
    };
    const double open_test = reference(scenes[0], skies[0].full, skies[0].zero_below_horizon);
    const double open_cie = reference(scenes[0], skies[1].full, skies[1].zero_below_horizon);

    for (const Scene& s : scenes) {
      shading::IntegrationOptions vo;
      vo.azimuths = g_azimuths;
      const sh::Vec v0 = shading::project_visibility(kOrder, s.occ, vo);
      const double ref_bl = reference(s, test_bl, false),
                   ref_test = reference(s, skies[0].full, skies[0].zero_below_horizon);
      const double ref_cie = reference(s, skies[1].full, skies[1].zero_below_horizon);
      const double tri_test = shading::shade_triple_product(gamma, v0, skies[0].sh, lobe, a);
      const double tri_cie = shading::shade_triple_product(gamma, v0, skies[1].sh, lobe, a);
      const double tab_test = tables[0]->shade(v0, a), tab_cie = tables[1]->shade(v0, a);
      char buf[512];
      std::snprintf(buf, sizeof buf, "| %s | %s | %.3f | %.6f | %s | %s | %.6f | %s | %s | %.6f | %s | %s |\n",
                    c.name.c_str(), s.name.c_str(), ref_test / open_test, ref_bl, pct(tri_test, ref_bl).c_str(),
                    pct(table_bl.shade(v0, a), ref_bl).c_str(), ref_test, pct(tri_test, ref_test).c_str(),
                    pct(tab_test, ref_test).c_str(), ref_cie, pct(tri_cie, ref_cie).c_str(),
                    pct(tab_cie, ref_cie).c_str());
      table_a += buf;
      worst_test.add(0, "triple", tri_test, ref_test, open_test);
      worst_test.add(1, "table", tab_test, ref_test, open_test);
      worst_cie.add(0, "triple", tri_cie, ref_cie, open_cie);
      worst_cie.add(1, "table", tab_cie, ref_cie, open_cie);

      const sh::Vec vp = pipeline_visibility(s);
      const double tri_p = shading::shade_triple_product(gamma, vp, skies[0].sh, lobe, a);
      const double tab_p = tables[0]->shade(vp, a);
      std::string row;
      for (const std::string& cell : {c.name, s.name, pct(tri_p, ref_test), pct(tab_p, ref_test)}) add_cell(row, cell);
      worst_pipe.add(0, "triple", tri_p, ref_test, open_test);
      worst_pipe.add(1, "table", tab_p, ref_test, open_test);
      std::size_t k = 2;
      for (double eps : kEpsilons) {
        const sh::Vec logv = log_visibility(s, eps);
        const sh::Vec loglobe = shading::log_brdf_zh(kOrder, c.brdf, eps);
        const double hyb = shading::shade_log_brdf(logv, skies[0].sh, loglobe, a);
        add_cell(row, pct(hyb, ref_test));
        char nm[64];
        std::snprintf(nm, sizeof nm, "log HYB ε=%g", eps);
        worst_pipe.add(k++, nm, hyb, ref_test, open_test);
        if (eps == 0.05 || eps == 0.1) {
          const double t1 = shading::shade_log_brdf(logv, skies[0].sh, loglobe, a, shading::LogExp::Pointwise);
          add_cell(row, pct(t1, ref_test));
          std::snprintf(nm, sizeof nm, "log T1 ε=%g", eps);
          worst_pipe.add(k++, nm, t1, ref_test, open_test);
        }
      }
      table_b += row;
      table_b += " |\n";
    }
  }

  std::printf("Skies: **test** L = 0.6 + 0.4z + 0.8·exp(6(ω·ŝ − 1)) on the whole sphere (math-notes §7/§8);\n");
  std::printf("**CIE 12** = CIE standard clear sky type 12, relative luminance, 0 below the horizon.\n");
  std::printf("Sun ŝ at elevation 35°, azimuth 40°. L̃ = order-4 SH projection of L.\n");
  std::printf("Lambert normal at elevation 70°, azimuth 200°; Phong axis R at elevation 55°, azimuth 60°.\n");
  std::printf("Spheres: over flat ground (σ = 0), centres in a 25° cone about elevation 60°, azimuth 40°.\n");
  std::printf("Brute force ∫ L·V·g dω: %d azimuths, exact in elevation. Order 4. Errors relative to the reference.\n\n",
              g_azimuths);
  std::printf("### A. Exact visibility (V = T0, the SH projection of the true binary visibility)\n\n");
  std::printf("lit = reference / unoccluded reference (test sky). triple uses L̃; table (L̃) is a table built from\n");
  std::printf("L̃ instead of L, to separate the shading error from the sky's band limit.\n\n");
  std::printf(
      "| BRDF | scene | lit | ref (L̃) | triple | table (L̃) | ref (L) | triple | table (L) | ref CIE | triple | table "
      "|\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n%s", table_a.c_str());

  std::printf("\n### B. End to end with the pipeline's visibility, test sky, against ref (L)\n\n");
  std::printf(
      "V: height field by wedge assembly (W = 32, NLP N = 8, linear); spheres as ground ⊗ HYB(Σ log, ε = 0.1).\n");
  std::printf("Log-BRDF: the log-visibility with the same ε as the log-BRDF (height-field log route, sphere\n");
  std::printf("accumulation), exp* by HYB (PS2 base, t = 0.25) or pointwise T1; sky L̃.\n\n");
  std::printf("| BRDF | scene | triple | table |");
  for (double eps : kEpsilons) {
    std::printf(" log HYB ε=%g |", eps);
    if (eps == 0.05 || eps == 0.1) std::printf(" log T1 ε=%g |", eps);
  }
  std::printf("\n|---|---|---|---|");
  for (double eps : kEpsilons) std::printf(eps == 0.05 || eps == 0.1 ? "---|---|" : "---|");
  std::printf("\n%s", table_b.c_str());

  std::printf("\n### C. Worst |error| over all BRDFs and scenes, as %% of the unoccluded radiance\n\n");
  std::printf("| setting |");
  for (const auto& n : worst_pipe.names) std::printf(" %s |", n.c_str());
  std::printf("\n|---|");
  for (std::size_t k = 0; k < worst_pipe.names.size(); ++k) std::printf("---|");
  std::printf("\n");
  auto row = [&](const char* name, const Worst& w) {
    std::printf("| %s |", name);
    for (std::size_t k = 0; k < worst_pipe.names.size(); ++k)
      if (k < w.err.size())
        std::printf(" %.2f%% |", 100 * w.err[k]);
      else
        std::printf(" — |");
    std::printf("\n");
  };
  row("exact V, test sky", worst_test);
  row("exact V, CIE 12", worst_cie);
  row("pipeline V, test sky", worst_pipe);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  std::printf("\n(%.1f s)\n", secs);
  return 0;
}
