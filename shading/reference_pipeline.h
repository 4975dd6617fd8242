// The CPU reference pipeline behind compute_product (products.h): per texel, horizons
// from the multi-resolution march or the exact march, then the product formulas;
// rows spread over worker threads. Double precision throughout; clear, not fast.
#pragma once

#include "shading/horizon/horizon_exact.h"
#include "shading/horizon/horizon_march.h"
#include "shading/progress.h"
#include "shading/products.h"
#include "shading/shading_modes.h"
#include "shading/sky_brdf_table.h"
#include "shading/sun_light.h"

#include <functional>
#include <memory>
#include <vector>

namespace skylit::shading {

// The horizon of one texel and heading, from either marcher; raw maxima, no floor.
// Whether compute_product finds `field`'s horizons by sweeping (horizon_sweep.h): the
// method asks for it, it applies (sweep_applicable), and the exact march is not asked
// for. Every backend decides by this.
bool uses_sweep(const terrain::HeightField& field, const ProductOptions& options);

class HorizonOracle {
 public:
  HorizonOracle(const terrain::HeightField& field, const ProductOptions& options);

  // Largest elevation angle (rad) along u from texel (i, j); −∞ if none on the grid.
  // Where uses_sweep: the exact march the sweep approximates (compute_product takes the
  // sweep's own horizons, which need the whole field's sweep lines).
  double max_elevation(int i, int j, horizon::Heading u) const;
  // The receiver's own ground level seen at the first march distance t₁ (the floor of
  // the `horizon` product): 0, or −atan(t₁/(2R_eff)) with Earth curvature. The sweep's
  // t₁ is the exact march's half texel.
  double ground_floor(int j, horizon::Heading u) const;

 private:
  const terrain::HeightField& field_;
  std::unique_ptr<horizon::HorizonMarcher> marcher_;  // null: exact march (or the sweep's half texel)
  horizon::ExactMarch exact_;
};

// Pieces of the lit products that every backend must share:
// the sun's march (sun_light.h) as the products' options set it (curvature, distance,
// exact); the radiance of output channel c of a sky (R, G, B when rgb, else the
// broadband luminance); and the tone map factor of lit `shaded` (lighting.h):
// code = display_code_value(E · shaded_display_scale, tone).
SunShadowOptions sun_shadow_options(const ProductOptions& options);
// The sky of unlit `shaded`: uniform radiance 1 above the horizontal, 0 below.
Radiance uniform_sky_radiance();
Radiance channel_radiance(std::shared_ptr<const sky::SkyModel> sky, bool rgb, int channel);
double shaded_display_scale(const ShadedOptions& shaded, const Lighting& lighting);
// Sky input of a Shader in `mode`: the full-frequency radiance (table mode) or its
// SH projection over the upper hemisphere (the skies are 0 below the horizon).
// z_symmetric: the radiance is symmetric about z (SkyInput); uniform_sky_radiance()
// is, a channel_radiance(sky, …) is if sky->azimuthally_symmetric().
SkyInput sky_input(ShadingMode mode, int order, Radiance radiance, bool z_symmetric);
// The Lambert shading settings of the sky light in `mode` at SH order `order`.
ShadingSettings sky_shading_settings(ShadingMode mode, int order);
// The sky inputs of a lighting's output channels (R, G, B when rgb, else the broadband
// luminance; none without a sky), as every backend shades them: in table mode a colour
// sky's three tables are built in one pass (SkyBrdfTable::rgb, equal to three).
std::vector<SkyInput> channel_sky_inputs(const Lighting& lighting, bool rgb, ShadingMode mode, int order);

}  // namespace skylit::shading
