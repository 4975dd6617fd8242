// Sphere blockers over one frame of a height field (DESIGN.md "Aircraft"): the spheres
// binned over the field's texels, and per texel the sun they leave and the change they
// make to the sky visibility, by the fast method (sky_blocking.h, disc_occlusion.h) or,
// with ProductOptions::exact, by the truth (visibility_truth.h: exact caps in elevation
// per azimuth; disc sampling for the sun).
#pragma once

#include "shading/blockers/sphere_bins.h"
#include "shading/products.h"
#include "shading/visibility_truth.h"
#include "terrain/height_field.h"

#include <span>
#include <vector>

namespace skylit::shading {

// The truth's size cull: caps below this solid-angle bound change no product by more
// than ~1e-7 (sphere_blocker.h's bound), and keeping every sphere everywhere would make
// the truth quadratic in texels × spheres.
inline constexpr double kTruthCullError = 1e-7;
// Disc samples of the truth's sun.
inline constexpr int kTruthDiscSamples = 4096;

// The receivers of a field for sphere bins (its texels, their spacing and height range).
blockers::ReceiverGrid receiver_grid(const terrain::HeightField& field);
// The blocker options of a frame: the cull error is each receiver's budget
// (receiver_budget.h), the truth's with ProductOptions::exact.
blockers::SkyBlockingOptions frame_blocking(const ProductOptions& options);
// The spheres and their groups binned over the field's texels for a frame, with the
// frame's blocker options (frame_blocking): the GPU uploads the same.
blockers::SphereBins frame_bins(const terrain::HeightField& field, std::span<const blockers::Sphere> spheres,
                                const blockers::SphereGroups& groups, const blockers::SkyBlockingOptions& blocking,
                                const ProductOptions& options);

class BlockerFrame {
 public:
  // The blockers' cull error is each receiver's budget for all spheres together (an
  // aircraft is many spheres each too small to matter alone).
  BlockerFrame(const terrain::HeightField& field, std::span<const blockers::Sphere> spheres,
               const ProductOptions& options);

  // Texel (i, j) in the field's frame (renderer.h FrameInputs): (i·dx, −j·dy, height).
  glm::dvec3 position(int i, int j) const;
  // Fraction of the sun disc (unit direction `sun`) the spheres leave at texel (i, j).
  double sun_left(int i, int j, const glm::dvec3& sun) const;
  // Whether any sphere may change the sky of texel (i, j).
  bool touches_sky(int i, int j) const { return !bins_.sky(i, j).empty(); }
  // ΔV = V − V_T at texel (i, j) (n² entries; `log_sum` gets f_T + f_S), from its
  // floored horizons at the math azimuths 2πk/W and the terrain's V_T and f_T made from
  // them. Returns the spheres kept (0: delta untouched). scratch: 3·n² doubles.
  int sky_delta(int i, int j, const glm::dvec3& normal, std::span<const double> sigma, std::span<const double> vis_t,
                std::span<const double> log_t, std::span<double> delta, std::span<double> log_sum,
                std::span<double> scratch) const;
  // The truth's ΔV: T0 of terrain and caps minus T0 of the terrain alone.
  void exact_sky_delta(int i, int j, std::span<const double> sigma, std::span<double> delta) const;
  // The truth's Δskyview ((1/π)∫ ΔV max(n·ω, 0) over the sky above the horizontal).
  double exact_skyview_delta(int i, int j, const glm::dvec3& normal, std::span<const double> sigma) const;

  // Spheres whose centre lies below the ground under it (reported by front ends: they
  // shade only what they reach).
  static int below_ground(const terrain::HeightField& field, std::span<const blockers::Sphere> spheres);

 private:
  Occluders occluders(int i, int j, std::span<const double> sigma, bool with_caps, double floor_at) const;
  int truth_azimuths(const std::vector<Cap>& caps) const;

  const terrain::HeightField& field_;
  std::span<const blockers::Sphere> spheres_;
  const ProductOptions& options_;
  blockers::SkyBlockingOptions blocking_;
  double disc_radius_;
  blockers::SphereGroups groups_;
  blockers::SphereBins bins_;
};

}  // namespace skylit::shading
