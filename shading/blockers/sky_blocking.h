// The sky visibility of a receiver under the terrain and sphere blockers (DESIGN.md
// "Aircraft", sky light; seed 000): the terrain's log-visibility plus each kept
// sphere's rotated log-ZH, exponentiated by HYB (sh_exp.h, with its guards). Texels
// where no sphere survives the culls keep the terrain's visibility and run no HYB.
#pragma once

#include "shading/blockers/sphere_blocker.h"
#include "shading/blockers/sphere_groups.h"
#include "shading/sh/sh_exp.h"

#include <cstdint>
#include <span>

namespace skylit::blockers {

// How the blocked visibility V is formed from the terrain's V_T and log-visibility f_T
// and the spheres' summed log-visibility f_S (docs/accuracy.md, aircraft):
enum class Composition {
  kLogSum,  // the seed: V = exp*(f_T + f_S)
  // V = V_T + exp*(f_T + f_S) − exp*(f_T): the seed's change added to the terrain's own
  // visibility, so V → V_T exactly as the spheres fade.
  kDelta,
  // V = V_T ∗ exp*(f_S), truncated SH product: the terrain's visibility untouched by
  // HYB, the spheres' by log*/exp*. Below a low aircraft skyview RMSE 0.00007–0.00035
  // (delta 0.00009–0.00048, log-sum 0.017); over a plane at r/d = 0.5: 0.0075 (delta
  // 0.025, log-sum 0.029); docs/accuracy.md.
  kProduct,
};

struct SkyBlockingOptions {
  BlockerOptions blocker;
  Composition composition = Composition::kProduct;
  sh::HybOptions hyb;
  // Cull spheres whose top lies below the terrain's horizon in their direction, and
  // merge no node across it.
  bool horizon_cull = true;
  // A node of a group's sphere tree whose bounding sphere a receiver sees within
  // asin(merge_sin) is one cap (sphere_groups.h; 0: never), unless it lies across the
  // receiver's horizon and its cull bound exceeds the cull budget (block_sky). Ten
  // airliners on the 1 m bench scene, cull off, merged against every sphere alone: skyview
  // within 3.5e-6 at 0.04, 6.9e-5 at 0.1; at the default budget 0.1 costs no more RMS
  // error than 0.04 and makes their products stage ~1.5x faster (docs/accuracy.md).
  double merge_sin = 0.1;
};

// One receiver. sigma: its horizon elevations (rad, floored at the tangent plane) at the
// math azimuths 2πk/W from +x toward +y; vis_t, log_t: the terrain's SH visibility and
// log-visibility (log ε_T · occlusion) from them (log_t may be empty for kProduct).
struct Receiver {
  glm::dvec3 position, normal;
  std::span<const double> sigma, vis_t, log_t;
};

// Where a sphere, seen from the receiver, lies against its horizon in the azimuths its
// cap spans: wholly below (its top under the lowest horizon sample there), wholly above
// (its bottom at or over the highest) or across. A cap wider than a quarter turn is
// never below, and above only when over every sample; no horizons: above.
enum class HorizonSide { kAbove, kBelow, kAcross };
HorizonSide horizon_side(const Sphere& s, const Receiver& r);

// For the groups listed in `candidates` less those the receiver's budget drops
// (options.blocker.cull_error; receiver_budget.h), each one cap where the receiver sees
// it as one and it lies wholly on one side of the horizon (a node across it takes its
// children, so no part of an aircraft hidden by the terrain darkens the sky through a
// merged cap; except a node whose cull bound is within the receiver's budget, whose
// hidden part costs at most that, merged without reading the horizon), else its
// members: writes delta = V − V_T and log_sum = f_T + f_S (the log-BRDF
// mode's input; f_S alone without log_t), n² entries each, and returns how many caps
// survived the culls (0: delta and log_sum are untouched). scratch holds 3·n² doubles.
// No allocation.
int block_sky(std::span<const Sphere> spheres, const SphereGroups& groups, std::span<const std::uint32_t> candidates,
              const Receiver& r, const SkyBlockingOptions& options, std::span<double> delta, std::span<double> log_sum,
              std::span<double> scratch);

}  // namespace skylit::blockers
