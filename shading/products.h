// Physical products of the CPU reference pipeline (DESIGN.md "Products"): the
// public entry point the `skylit shade` CLI calls. Every product is computed in
// double precision per texel and returned as float bands.
//
// Definitions (tests rely on them; σ_k = marched horizon elevation at azimuth k):
//  * horizon : σ_k in degrees, one band per geographic azimuth A_k = k·360°/W (from
//              north, clockwise). σ_k is the largest elevation angle of the terrain
//              along the ray, seen from the texel centre's own height, never below the
//              receiver's own ground level: ≥ 0 on flat or falling ground — only the
//              Earth-curvature drop makes it negative (−atan(t₁/(2R_eff)) with t₁ the
//              first march distance on a flat plane).
//  * svf     : 1 − (1/W)·Σ_k sin(max(σ_k, 0))  (Zakšek et al. 2011).
//  * skyview : (1/π)∫ V(ω) max(n·ω, 0) dω, sky above the horizontal only, n the Horn
//              normal; per azimuth slice the elevation integral is exact (closed form)
//              over e ∈ (max(σ_k, 0), π/2], midpoint rule over the W slices. Open flat
//              ground gives 1, a tilted open plane (1 + cos s)/2.
//  * shaded  : relief under a uniform sky of radiance 1 (above the horizontal), SH
//              visibility from the marched horizons (wedge assembly) shaded by the
//              default sky×BRDF table of shading_modes, Lambert albedo; outgoing
//              radiance → exposure → sRGB → 8-bit code values 1…255 as floats (0 is
//              left for nodata, as gdaldem does). With ProductOptions::lighting the
//              sky and sun of lighting.h instead: radiance albedo/π·(E_sky + E_sun) per
//              channel (3 bands R, G, B when the lighting is colour), tone-mapped as
//              lighting.h states.
//  * shadow  : visible fraction of the solar disc (sun_light.h: the sun's own march, or
//              the exact march with `exact`), 0…1; 0 while the sun's centre is below the
//              horizon (renderer.h night_shadow). Needs lighting (its sun direction).
//  * irradiance: W/m² on the surface, broadband (luminance of RGB):
//              E_sky = ∫ L·V·max(n·ω, 0) dω = π·Σ_k V_k·T_k(n) (the SH visibility of
//              `shaded` and a Lambert sky table of the lighting's sky), plus
//              E_sun = DNI·max(n·s, 0)·shadow. Needs lighting. Clamped at 0.
//  * hillshade : gdaldem's hillshade (relief/gdal_hillshade.h) with ProductOptions::hillshade,
//              8-bit code values 1…255, bit-exact with gdaldem 3.6 (docs/gdaldem.md).
// Nodata texels are NaN in every band (the writer maps NaN to nodata).
#pragma once

#include "shading/blockers/sky_blocking.h"
#include "shading/horizon/horizon_march.h"
#include "shading/lighting.h"
#include "shading/progress.h"
#include "shading/relief/gdal_hillshade.h"
#include "shading/sh/wedge.h"
#include "shading/shading_modes.h"
#include "terrain/height_field.h"

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace skylit::shading {

// New products are appended: the GPU hands the enum's values to its shaders.
enum class Product { Horizon, Svf, Skyview, Shaded, Shadow, Irradiance, Hillshade };

// What kind of result a product is: the one table every backend and front end reads
// (nothing else tests for particular products to decide these).
struct ProductTraits {
  Product product;
  std::string_view name;          // "horizon", "svf", …
  bool band_per_azimuth = false;  // one band per azimuth of the march (horizon); else one band
  bool rgb_when_colour = false;   // R, G, B bands when the lighting is colour (shaded)
  bool needs_visibility = false;  // SH visibility from the horizons, shaded by sky tables (shaded, irradiance)
  bool lit = false;               // uses ProductOptions::lighting: always (needs_sun) or when it is set (shaded)
  bool needs_sun = false;         // requires the lighting's sun and sky (shadow, irradiance)
  bool sun_only = false;          // the sun's shadow pass alone, no sky horizons (shadow)
  bool eight_bit = false;         // 8-bit code values 1…255 as floats, 0 left for nodata (shaded, hillshade)
  bool blocked = false;           // sphere blockers darken it (skyview, shaded, shadow, irradiance)
  // A 3×3-window product computed on the host from the heights (local_products.h):
  // no horizons, no lighting, no GPU work; every renderer hands it to compute_local_product.
  bool local = false;
};

// Every product's traits, in the enum's order.
std::span<const ProductTraits> all_product_traits();
// The row of `p`; throws std::invalid_argument for a value outside the enum.
const ProductTraits& traits(Product p);

// traits(p).name; "unknown" for a value outside the enum.
std::string_view product_name(Product p);
// "horizon", "svf", "skyview", "shaded", "shadow", "irradiance", "hillshade"; nullopt otherwise.
std::optional<Product> parse_product(std::string_view name);
// The names above joined by ", " (for messages).
std::string product_names();
// Name of band k of W of the horizon product, e.g. "horizon_az045.0".
std::string horizon_band_name(int k, int azimuths);

struct ExactOptions {
  int sky_azimuths = 360;       // svf/skyview ground truth: azimuths of the sky integral
  double step_texels = 0.5;     // march step, in texels along the ray's dominant axis
};

// How `shaded`'s linear display value becomes an 8-bit code: the sRGB curve, for pictures
// (colour skies), or linear codes as hillshades store them (gdaldem's 255·cos): a grey
// relief that is multiplied with other layers in a GIS, and keeps the contrast of the
// sun side against the sky side that the sRGB curve flattens (docs/gallery.md).
enum class ToneCurve { Srgb, Linear };

struct ShadedOptions {
  // How V meets the sky (docs/numerics.md §3): the sky×BRDF table is the most accurate
  // at the same per-texel cost; triple product and the seed's log-BRDF are selectable.
  ShadingMode mode = ShadingMode::SkyBrdfTable;
  double albedo = 1.0;          // Lambert albedo
  double exposure = 1.0;        // linear radiance multiplier before the tone curve
  ToneCurve tone = ToneCurve::Srgb;
  int sh_order = 4;             // n: SH bands of the visibility
  int nlp_order = 8;            // N ≥ n (N = 2n removes most of the odd-|m| floor)
  // Wedge interpolation of the slices over azimuth: linear (M_lin, n²×2N) or cubic
  // B-spline (M_bspl, n²×4N), DESIGN.md step 4.
  sh::WedgeInterpolation wedge = sh::WedgeInterpolation::Linear;
};

struct ProductOptions {
  horizon::MarchOptions march;  // W, k_v, n_v, o_v, max distance, curvature, smoothing
  bool exact = false;           // ground truth: dense half-texel march (see horizon_exact.h)
  ExactOptions exact_options;
  ShadedOptions shaded;
  // Horizon sub-sampling s ∈ {1, 2, 4} (DESIGN.md step 4, NS09 §7). Coarse positions
  // per axis: 0, s, 2s, … and always the last index (shading/horizon/horizon_subsample.h). The
  // raw horizons σ_k (before any floor) of the coarse texels are marched or swept exactly
  // as with s = 1; every other texel mixes them linearly in each axis between its
  // bracketing coarse positions (bilinear: one, two or four samples). Where one of those
  // samples is nodata or its σ_k is not finite (−∞: no step on the grid, at edges), the
  // march marches the texel's own ray for that azimuth, and the sweep (whose far slopes
  // exist for the coarse texels alone) mixes the finite samples, their weights
  // renormalised (−∞ if none). Normals, floors (receiver ground, tangent plane),
  // svf/skyview formulas, NLP slices, wedges and shading stay per texel; the sun's shadow
  // is never sub-sampled. `exact` (the ground truth) is rejected with s > 1.
  int subsample = 1;
  unsigned threads = 0;         // worker threads over rows; 0 = hardware concurrency
  // Sky + sun (lighting.h). Required by shadow and irradiance; for shaded it replaces
  // the uniform sky of radiance 1 (the default, kept when empty).
  std::optional<Lighting> lighting;
  // Sphere blockers (FrameInputs::spheres): ε, culling, composition, HYB.
  blockers::SkyBlockingOptions blockers;
  // gdaldem's hillshade (the hillshade product; its z applies inside the formula).
  relief::HillshadeOptions hillshade;
};

// Throws std::invalid_argument unless ProductOptions::subsample is 1, 2 or 4, and for
// sub-sampling with `exact`.
void validate_subsample(const ProductOptions& options);

// True when `product` with `options` uses the lighting (sun shadows, sky tables of a
// lit sky): shadow, irradiance, and shaded with options.lighting set.
bool uses_lighting(Product product, const ProductOptions& options);
// True when its bands are R, G, B: a lit rgb_when_colour product under a colour lighting.
bool rgb_bands(Product product, const ProductOptions& options);
// Number and names of its bands: W azimuths ("horizon_az045.0", …), "red", "green",
// "blue", or one band named after the product.
int band_count(Product product, const ProductOptions& options);
std::vector<std::string> band_names(Product product, const ProductOptions& options);

// Float bands, band-major: value(b, i, j) = data[(b·height + j)·width + i].
struct ProductBands {
  int width = 0;
  int height = 0;
  int bands = 0;
  std::vector<float> data;
  std::vector<std::string> band_names;  // e.g. "horizon_az045.0" (degrees from north)

  float at(int b, int i, int j) const {
    return data[(static_cast<std::size_t>(b) * height + j) * width + i];
  }
};

// Computes `product` for every texel of `field`. Throws std::invalid_argument on bad
// options (W < 1, k_v < 1, negative distances, …).
ProductBands compute_product(const terrain::HeightField& field, Product product, const ProductOptions& options,
                             const ProgressCallback& progress = {});

// Per-texel formulas of the products from horizon elevations (radians) at
// geographic azimuths A_k = k·2π/W; normal in (east, north, up), unit.
double svf_from_horizon(const std::vector<double>& sigma);
double skyview_from_horizon(const std::vector<double>& sigma, const glm::dvec3& normal);
// The same for horizons at W evenly spread `headings` of one's own (the SH visibility's
// math azimuths 2πk/W, say).
double skyview_from_horizon(std::span<const double> sigma, std::span<const horizon::Heading> headings,
                            const glm::dvec3& normal);

// (1/π)·∫_{e ∈ (lo, π/2]} max(n·ω(e), 0) cos e de for the horizontal unit direction u
// (east, north) of one azimuth: the exact elevation integral of one skyview slice
// (multiply by Δφ and sum over slices).
double skyview_slice_integral(double lo, const glm::dvec3& normal, double u_east, double u_north);

// The sRGB transfer curve (IEC 61966-2-1) and the code range of 8-bit products (0 is
// nodata): here once, for the host and, as generated #defines, the viewer's shaders.
inline constexpr double kSrgbLinearLimit = 0.0031308;  // linear segment below
inline constexpr double kSrgbLinearSlope = 12.92;
inline constexpr double kSrgbScale = 1.055, kSrgbOffset = 0.055, kSrgbGamma = 2.4;
inline constexpr double kFirstCode = 1.0, kCodeSpan = 254.0;  // codes 1 … 255

// 8-bit sRGB code value (1…255) of a linear radiance after exposure.
float srgb_code_value(double linear);
// 8-bit code value (1…255) of a linear display value by `tone`: sRGB, or 1 + 254·x.
float display_code_value(double linear, ToneCurve tone);
// The display value of open flat ground at the tone map's E_ref (lighting.h): kShadedKey
// under the sRGB curve (headroom for slopes facing a low sun, which reach about E_ref);
// 1 under the linear curve, which then matches gdaldem's cos = 1 → 255.
inline double shaded_key(ToneCurve tone) { return tone == ToneCurve::Srgb ? kShadedKey : 1.0; }

}  // namespace skylit::shading
