// The sun as a key light on a height field (DESIGN.md pipeline step 8, products
// `shadow` and the sun part of `irradiance`).
//
// Per texel the terrain horizon is sampled at azimuths across the solar disc
// (sun_disc.h frame: column x ∈ [−1, 1] sits at azimuth A_s + x·r/cos e_s) and the disc
// is integrated exactly above the piecewise-linear horizon through those samples and
// above the surface's tangent plane (Horn normal; sun below it → 0, partial disc at
// the terminator). The horizon samples come from
//  * Marched      — a march in the exact sun azimuth (HorizonMarcher schedule), and
//                   with disc_slope also at A_s ± δ (δ = the disc's azimuth
//                   half-width), giving the horizon's slope across the disc;
//  * Interpolated — linear interpolation between the two product azimuths
//                   A_k = k·2π/W that bracket each column (what the W-azimuth sky
//                   march already computes);
//  * Exact        — the dense half-texel march (horizon_exact.h) at `exact_columns`
//                   azimuths across the disc: the ground truth;
//  * Swept        — the horizon sweep (horizon_sweep.h) in the exact sun azimuth, with
//                   the march options' near steps and lines (sun_march_options': 8, 3),
//                   where it applies (sun_sweeps); elsewhere Marched.
// Horizons are raw maxima: there is no floor at the astronomical horizon, so a ridge
// top sees a sun slightly below 0°; its DNI is 0 there anyway (atmosphere.h).
#pragma once

#include "shading/horizon/horizon_exact.h"
#include "shading/horizon/horizon_march.h"
#include "shading/progress.h"
#include "shading/sky/atmosphere.h"
#include "terrain/height_field.h"

#include <glm/vec3.hpp>

#include <numbers>
#include <vector>

namespace skylit::shading {

enum class SunHorizon { Marched, Interpolated, Exact, Swept };

// The march the sun needs (docs/accuracy.md (sun shadows)): level-0 bilinear heights at
// k_v = 32 steps per halving of distance, plain max. The sky's march (B-spline pyramid,
// k_v = 4, smoothed max) lowers ridges by more than the disc's radius: ~5% of low-sun
// texels flip from shadow to lit. The sun marches 1 ray, not W, so it can afford this.
// Likewise its sweep (Swept): K = 8 near steps, 3 lines per texel (0.05 % flips where
// the sky's K 4, 1 line gives 0.30 %).
horizon::MarchOptions sun_march_options();

struct SunShadowOptions {
  SunHorizon horizon = SunHorizon::Marched;
  // Marched: the sun's own march. Interpolated: pass the sky's march (W = march.azimuths).
  horizon::MarchOptions march = sun_march_options();
  // Marched: also march at A_s ± δ (3 rays instead of 1). Measured to matter little on
  // 30–90 m DEMs (penumbra error 0.074 → 0.070), so off by default.
  bool disc_slope = false;
  horizon::ExactMarch exact;   // Exact: step, max distance, curvature
  int exact_columns = 17;      // Exact: azimuth samples across the disc, 2…65
  double radius = sky::kSunAngularRadius;  // angular radius of the disc (rad)
  unsigned threads = 0;        // workers over rows (and the sweep's lines); 0 = hardware concurrency
};

// Whether shadow_fraction_field sweeps the sun's horizon on `field` (Swept, and the
// sweep applies to it); every backend decides by this.
bool sun_sweeps(const terrain::HeightField& field, const SunShadowOptions& options);

// The sun's sweep needs a far slope exactly only where it may reach the disc: the floor
// (tan) under which horizon::sweep_far_slopes may lower it lies kSunFloorMargin below
// the disc's lowest edge, e − r − margin. A margin ≥ r keeps every result bit for bit:
// a horizon under the floor sits 2 radii or more below the disc's centre, where the
// clip square [−2, 2]² of sun_disc.h (and sun_shadow.comp's closed form) no longer sees
// it. Frames that keep the swept horizon for a later sun
// (GpuProductPipeline::set_sun_heading_tolerance) may take it while the sun stands at
// most kSunFloorMargin / 2 lower. Below kSunFloorMinElevation, −∞ (no floor): a low
// sun's floor settles too few texels to pay for the bound (BM_SunSweepFloor; measured
// in docs/performance.md, session 33: the break-even lies at 15–30° by the DEM).
inline constexpr double kSunFloorMargin = 1.0 * std::numbers::pi / 180.0;
inline constexpr double kSunFloorMinElevation = 30.0 * std::numbers::pi / 180.0;
double sun_sweep_floor(double elevation, const SunShadowOptions& options);

// Throws std::invalid_argument on bad options (radius ∉ (0, π/4), columns ∉ [2, 65],
// bad march options).
void validate(const SunShadowOptions& options);

// Sun position: geographic azimuth (from north, clockwise) and elevation, radians.
struct SunAngles {
  double azimuth = 0.0;
  double elevation = 0.0;
};

// Fraction of the solar disc visible from every texel, row-major (width·height);
// NaN where the texel is nodata. 0 = full shadow, 1 = lit.
std::vector<float> shadow_fraction_field(const terrain::HeightField& field, SunAngles sun,
                                         const SunShadowOptions& options = {}, const ProgressCallback& progress = {});

// Direct sun irradiance on a surface (W/m²): DNI·max(n·s, 0)·fraction; n, s unit.
double sun_irradiance(const glm::dvec3& normal, const glm::dvec3& sun_direction, double dni, double fraction);
sky::Rgb sun_irradiance(const glm::dvec3& normal, const sky::Sun& sun, double fraction);

// Unit direction toward the sun (east, north, up) for geographic azimuth and elevation.
glm::dvec3 sun_direction(SunAngles sun);

}  // namespace skylit::shading
