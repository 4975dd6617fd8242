#include "gpu/gpu_pipeline.h"

#include "shading/horizon/horizon_ray.h"
#include "shading/reference_pipeline.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "gpu/buffers.h"
#include "gpu/compute_program.h"
#include "gpu/gl_context.h"
#include "gpu/gpu_blockers.h"
#include "gpu/gpu_pyramid.h"
#include "gpu/resident_field.h"
#include "gpu/shading_setup.h"
#include "gpu/timer.h"
#include "gpu/visibility_refresh.h"
#include "gpu/wedge_fourier.h"
#include "shading/horizon/azimuth.h"
#include "shading/horizon/horizon_march.h"
#include "shading/horizon/horizon_subsample.h"
#include "shading/horizon/horizon_sweep.h"
#include "shading/lighting.h"
#include "shading/sh/nlp.h"
#include "shading/sh/wedge.h"
#include "shading/shading_modes.h"
#include "shading/sun_light.h"
#include "terrain/pyramid.h"

namespace skylit::gpu {
namespace {

using shading::Product;

// Storage-buffer binding points, handed to the shaders as generated #defines.
enum Binding : int {
  kHeights = 0,
  kRowDx = 1,
  kHeadings = 2,
  kSigma = 3,
  kValid = 4,
  kOutput = 5,
  kSchedule = 6,  // a uniform block (horizon_march.comp)
  kCoeffs = 8,
  kFar = 9,       // texture unit of the sweep's far-slope codes (surface_products.comp, sun_shadow.comp)
  kTable = 11,
  kShadow = 12,
  kSunSchedule = 13,
  kCoarseSigma = 14,
  kVis = 16,  // the kept visibility (surface_products.comp, VIS_CACHE)
  kSweepGamma = 17,  // horizon_sweep.comp on curved rows: Γ of the half rows, in double
  kSweepRowDx = 18,  // and the rows' spacings in double
  kKeptHorizons = 19,  // a blocked pipeline's kept floored horizons (surface_products.comp)
  kKeptSky = 20,       // the kept sky irradiance (surface_products.comp, SKY_CACHE)
  kSunKept = 21,       // the sun's kept horizon elevations (sun_shadow.comp, SUN_KEPT)
  kSunList = 22,       // the texels a kept frame's sun pass shades (sun_shadow.comp, SUN_LIST)
};

// Texture units of the sphere blockers' buffer textures (sphere_blockers.glsl), apart
// from the units the kernels' other samplers use (kHeights, kRowDx, kSigma, kCoeffs,
// kFar, kTable).
constexpr BlockerBindings kBlockerBindings{4, 5, 6, 7, 10, 12};
constexpr int kGammaUnit = 13;  // Γ's buffer texture (sh_product.glsl)

// Steps the march kernel's uniform step table holds (8 KiB, under GL's 16 KiB minimum
// block size): k_v = 16 over a 16384² grid's diagonal needs 234.
constexpr int kMaxMarchSteps = 256;
constexpr int kLocalSize = 8;  // 8×8 texels per work group
constexpr int kSweepLocalSize = 64;  // sweep lines per work group
constexpr int kFarImageUnit = 0;     // horizon_sweep.comp's uimage2DArray of far-slope codes
constexpr int kHullImageUnit = 1;    // and its image2D of convex hulls
constexpr int kHeldImageUnit = 2;    // a bounded search's samples entered (rgba32f),
constexpr int kFarHullImageUnit = 3; // the older samples' hull (rg32f)
constexpr int kHiddenImageUnit = 4;  // and the vertices its pushes hid (rg32f)
// Hull scratch per sweep dispatch: lines × samples × 8 B (and ≤ GL_MAX_TEXTURE_SIZE
// lines); a heading's lines go in as many dispatches as the budget needs, each of at
// least kMinSweepGroups work groups (both llvmpipe threads busy, and their tails
// balanced). On a software rasterizer the budget is small: fresh memory is dear there
// (≈ 3 ms per MiB of first touch on the 2-core CI VM; 16 → 4 MiB took 1024²'s sweep
// from 1.14 to 1.01 s), and 2×8 SIMD lanes need few lines in flight. A GPU wants every
// line of a heading in one dispatch.
constexpr std::size_t kSoftwareHullBudgetBytes = std::size_t{4} << 20;
constexpr std::size_t kHullBudgetBytes = std::size_t{512} << 20;
constexpr int kMinSweepGroups = 4;

bool software_renderer() {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return is_software_renderer(renderer ? renderer : "");
}

using Clock = std::chrono::steady_clock;

// Bands of the raw horizons a product needs, as compute_product chooses them.
int horizon_bands(Product product, const shading::ProductOptions& o) {
  if (shading::traits(product).band_per_azimuth) return o.march.azimuths;
  return o.exact ? o.exact_options.sky_azimuths : o.march.azimuths;
}

bool needs_visibility(Product product) { return shading::traits(product).needs_visibility; }

// Whether the product kernel computes the SH visibility: shaded and irradiance, and a
// skyview with sphere blockers (their change is shaded by the uniform sky's table).
bool sh_visibility(Product product, bool blocked) { return needs_visibility(product) || (blocked && product == Product::Skyview); }

// Headings as compute_product uses them: geographic bands for horizon, svf and skyview;
// the wedge operator's math-frame samples φ_j = j·2π/W for shaded and irradiance.
// Snapped (see shading/horizon/azimuth.h) so cardinal rays along the grid's edges stay on it.
std::vector<horizon::Heading> band_headings(Product product, int w, bool blocked) {
  std::vector<horizon::Heading> out;
  for (int k = 0; k < w; ++k)
    out.push_back(sh_visibility(product, blocked) ? horizon::heading_from_math(horizon::kTwoPi * k / w)
                                            : horizon::heading_from_geographic(horizon::band_azimuth(k, w)));
  return out;
}

// The far-slope codes' constants (shading/horizon/horizon_sweep.h), for the kernels that
// write or read them.
GlslDefines& add_far_code_defines(GlslDefines& d) {
  return d.set("FAR_CODE_HALF_RANGE", horizon::kFarCodeHalfRange).set("FAR_CODE_MAX", horizon::kFarCodeMax);
}

// The defines of a kernel that finds texels' own sweep horizons (horizon_near.glsl):
// their near steps, the far codes' texture unit and constants, and one row spacing.
GlslDefines& add_swept_defines(GlslDefines& d, const shading::ProductOptions& o, bool one_dx) {
  d.set("ONE_DX", one_dx ? 1 : 0).set("NEAR_STEPS", o.march.sweep_near_steps).set("FAR_BINDING", kFar);
  return add_far_code_defines(d);
}

GlslDefines common_defines(int azimuths, const shading::ProductOptions& o) {
  GlslDefines d;
  d.set("LOCAL_SIZE_X", kLocalSize)
      .set("LOCAL_SIZE_Y", kLocalSize)
      .set("AZIMUTHS", azimuths)
      .set("INV_TWO_R_EFF", o.march.curvature.drop_per_square_metre())
      .set("HEIGHTS_BINDING", kHeights)
      .set("ROW_DX_BINDING", kRowDx)
      .set("HEADINGS_BINDING", kHeadings)
      .set("SIGMA_BINDING", kSigma);
  return d;
}

void set_grid_uniforms(const ComputeProgram& p, const terrain::HeightField& f) {
  p.set_uniform("grid_width", f.width);
  p.set_uniform("grid_height", f.height);
  if (p.has_uniform("grid_dy")) p.set_uniform("grid_dy", static_cast<float>(f.dy));
  if (p.has_uniform("edge_eps")) p.set_uniform("edge_eps", static_cast<float>(horizon::edge_epsilon_texels(f)));
}

// compute_product's argument checks, before any kernel is built.
void validate_options(Product product, const shading::ProductOptions& o) {
  shading::validate_subsample(o);
  if (!gpu_supports(product, o))
    throw std::invalid_argument("the GPU pipeline cannot compute '" + std::string(shading::product_name(product)) +
                                "' with these options (a lit product needs ProductOptions::lighting and "
                                "the multi-resolution march)");
  horizon::validate(o.march);
  if (o.exact && !(o.exact_options.step_texels > 0.0)) throw std::invalid_argument("exact: step must be > 0");
  if (horizon_bands(product, o) < 1) throw std::invalid_argument("exact: sky azimuths must be ≥ 1");
  if (!(o.shaded.albedo >= 0.0) || !(o.shaded.exposure > 0.0))
    throw std::invalid_argument("shaded: albedo must be ≥ 0 and exposure > 0");
  if (shading::uses_lighting(product, o)) shading::validate(*o.lighting);
}

bool bilinear_levels(const horizon::MarchOptions& o) {
  return horizon::level_sampling(o) == horizon::LevelSampling::Bilinear;
}

// Whether the sun contributes (reference: luminance of the DNI > 0); else no shadow pass.
bool sun_lit(Product product, const shading::ProductOptions& o) {
  return shading::uses_lighting(product, o) && sky::luminance(o.lighting->sun.dni) > 0.0;
}

// The sweep's textures, kept between compute() calls while their sizes stay: fresh memory
// is dear (≈ 3 ms per MiB of first touch on the CI VM, 0.4 s for 1024²'s far slopes),
// and a time series, the viewer or the bench computes the same size again and again.
struct SweepTextures {
  TextureArray far, sun_far;
  Texture2D hull, held, far_hull, hidden;  // the last three: a bounded search's window
  std::array<int, 3> far_size{}, sun_far_size{}, hull_size{}, window_size{};

  static const TextureArray& array(TextureArray& t, std::array<int, 3>& size, int w, int h, int layers) {
    if (size != std::array{w, h, layers}) {
      t = TextureArray();  // free the old one first
      t = TextureArray(w, h, layers);
      size = {w, h, layers};
    }
    return t;
  }
  const Texture2D& hull_of(int lanes, int samples) {
    if (hull_size != std::array{lanes, samples, 0}) {
      hull = Texture2D();
      hull = Texture2D(lanes, samples, TextureFormat::RG32F);
      hull_size = {lanes, samples, 0};
    }
    return hull;
  }
  // Binds the window's scratch: lanes × samples where bounded, else 1 × 1 (the kernel
  // declares the images but does not touch them).
  void bind_window(int lanes, int samples, bool bounded) {
    const std::array size = bounded ? std::array{lanes, samples, 0} : std::array{1, 1, 0};
    if (window_size != size) {
      held = Texture2D(), far_hull = Texture2D(), hidden = Texture2D();
      held = Texture2D(size[0], size[1], TextureFormat::RGBA32F);
      far_hull = Texture2D(size[0], size[1], TextureFormat::RG32F);
      hidden = Texture2D(size[0], size[1], TextureFormat::RG32F);
      window_size = size;
    }
    held.bind_image(kHeldImageUnit, true, true);
    far_hull.bind_image(kFarHullImageUnit, true, true);
    hidden.bind_image(kHiddenImageUnit, true, true);
  }
};

// Stage 2 with the sweep (shading/horizon/horizon_sweep.h): horizon_sweep.comp for every band's
// lines into `far` (one layer per band), in dispatches whose hull scratch fits the budget.
// Without a kernel (Impl::sweep_kernel on the host), the same lines swept on the host's cores instead,
// layer by layer.
// The host takes a floor for the slopes (horizon::sweep_far_slopes; the kernel sweeps
// every slope exactly, which the floor allows).
// `observer_step`: a sub-sampled field's, whose coarse texels' far slopes alone are read
// (horizon::sweep_far_slopes; the kernel sweeps every texel).
void sweep_pass(const ComputeProgram* kernel, const terrain::HeightField& field, const horizon::MarchOptions& o,
                const std::vector<horizon::Heading>& headings, const TextureArray& far, SweepTextures& textures,
                double floor_slope = -std::numeric_limits<double>::infinity(), int observer_step = 1) {
  if (!kernel) {
    for (std::size_t k = 0; k < headings.size(); ++k)
      far.upload_layer(static_cast<int>(k),
                       horizon::sweep_far_slopes(field, headings[k], o, 0, floor_slope, observer_step));
    return;
  }
  const ComputeProgram& sweep = *kernel;
  std::vector<horizon::SweepGeometry> geometry;
  int max_samples = 1;
  const bool curved = !horizon::one_row_spacing(field);
  const auto rows = curved ? std::make_shared<const horizon::RhumbRows>(field) : nullptr;
  for (const horizon::Heading& u : headings) {
    geometry.push_back(horizon::sweep_geometry(field, u, o.sweep_lines, rows));
    max_samples = std::max(max_samples, geometry.back().samples);
  }
  // A bounded search's window holds 8 more floats a sample (held, far hull, hidden).
  const bool bounded = horizon::sweep_bounded(field, o);
  const std::size_t per_line = static_cast<std::size_t>(max_samples) * (bounded ? 10 : 2) * sizeof(float);
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  if (max_samples > max_size)
    throw std::runtime_error("GPU sweep: a line of " + std::to_string(max_samples) +
                             " samples exceeds GL_MAX_TEXTURE_SIZE " + std::to_string(max_size) + " (the sweep takes " +
                             std::to_string((max_size + 1) / 2) +
                             " texels along an azimuth; the march method has no such limit)");
  int lanes = 1;
  for (const horizon::SweepGeometry& g : geometry) lanes = std::max(lanes, g.lines);
  const std::size_t budget = software_renderer() ? kSoftwareHullBudgetBytes : kHullBudgetBytes;
  const std::size_t budget_lanes = std::max<std::size_t>(kMinSweepGroups * kSweepLocalSize, budget / per_line);
  lanes = static_cast<int>(std::min<std::size_t>({static_cast<std::size_t>(lanes), static_cast<std::size_t>(max_size),
                                                  budget_lanes}));
  textures.hull_of(lanes, max_samples).bind_image(kHullImageUnit, true, true);
  textures.bind_window(lanes, max_samples, bounded);
  far.clear(horizon::kFarCodeNone);
  far.bind_image(kFarImageUnit, false, true);
  // Curved rows' tables in double (bound also when unused: the kernel declares them).
  const std::vector<double> no_rows{0.0};
  const std::vector<double>& gamma = curved ? rows->half_rows() : no_rows;
  const std::vector<double>& row_dx = curved ? field.dx_per_row : no_rows;
  const Buffer gamma_buffer = Buffer::from(std::span<const double>(gamma));
  const Buffer row_dx_buffer = Buffer::from(std::span<const double>(row_dx));
  gamma_buffer.bind_storage(kSweepGamma);
  row_dx_buffer.bind_storage(kSweepRowDx);
  set_grid_uniforms(sweep, field);
  sweep.set_uniform("stride", lanes);
  sweep.set_uniform("curved", curved ? 1 : 0);
  sweep.set_uniform("d_ref", curved ? rows->d_ref() : 1.0);
  for (std::size_t k = 0; k < geometry.size(); ++k) {
    const horizon::SweepGeometry& g = geometry[k];
    sweep.set_uniform("band", static_cast<int>(k));
    sweep.set_uniform("x_dominant", g.x_dominant ? 1 : 0);
    sweep.set_uniform("delta_a", static_cast<float>(g.delta_a));
    sweep.set_uniform("extent_a", g.extent_a);
    sweep.set_uniform("extent_b", g.extent_b);
    sweep.set_uniform("samples", g.samples);
    sweep.set_uniform("lines", g.lines);
    sweep.set_uniform("r_f", static_cast<float>(g.r));
    sweep.set_uniform("c_low_f", static_cast<float>(g.c_low));
    sweep.set_uniform("spacing_f", static_cast<float>(g.spacing()));
    sweep.set_uniform("r_d", g.r);
    sweep.set_uniform("c_low_d", g.c_low);
    sweep.set_uniform("spacing_d", g.spacing());
    sweep.set_uniform("drop", static_cast<float>(o.curvature.drop_per_square_metre() * g.step_m * g.step_m));
    sweep.set_uniform("step_m", static_cast<float>(g.step_m));
    sweep.set_uniform("bounded", bounded ? 1 : 0);
    sweep.set_uniform("limit_steps", static_cast<float>(bounded ? horizon::sweep_window_steps(field, g, o) : 0.0));
    for (int first = 0; first < g.lines; first += lanes) {
      sweep.set_uniform("line_offset", first);
      sweep.dispatch_covering(std::min(lanes, g.lines - first));
    }
  }
}

// SunHorizon::Swept (shading::sun_sweeps): the far slopes of the sun's heading (one
// layer), by horizon_sweep.comp on the resident heights and row spacings, which must be
// bound as buffer textures, or on the host without a kernel.
const TextureArray& sun_far_slopes(const ComputeProgram* sweep, const terrain::HeightField& field,
                                   const shading::ProductOptions& o, horizon::Heading u, SweepTextures& textures) {
  const TextureArray& far =
      SweepTextures::array(textures.sun_far, textures.sun_far_size, field.width, field.height, 1);
  const shading::SunShadowOptions sun = shading::sun_shadow_options(o);
  sweep_pass(sweep, field, sun.march, {u}, far, textures, shading::sun_sweep_floor(sky::elevation_of(o.lighting->sun.direction), sun));
  return far;
}

// Stage 0 (lit products with a sun, and shadow): sun_shadow.comp over the whole field
// into `shadow` (4 B/texel), in row chunks of ≤ `invocations` texels. Heights, row
// spacing and the valid mask must be bound; the step schedule goes to `schedule_buf`
// (re-uploaded only when it changed: `uploaded` grows by its bytes). Returns the GPU
// time (ms).
double sun_pass(const ComputeProgram& sun, const terrain::HeightField& field, const shading::ProductOptions& o,
                std::size_t invocations, ResidentTable& schedule_buf, std::size_t& uploaded, Buffer& shadow,
                const TextureArray* far) {
  check_storage_size(field.size() * sizeof(float), "GPU pipeline: the sun shadow");
  shadow = Buffer(field.size() * sizeof(float));
  shadow.bind_storage(kShadow);
  set_grid_uniforms(sun, field);
  if (far) {  // SunHorizon::Swept: the sun's far slopes, swept already
    far->bind_sampler(kFar);
  } else {
    const horizon::MarchSchedule steps = horizon::march_schedule(field, shading::sun_shadow_options(o).march);
    std::vector<float> schedule;
    for (double t : steps.distances) {
      schedule.push_back(static_cast<float>(t));
      schedule.push_back(0.0f);
    }
    uploaded += schedule_buf.assign(schedule);
    schedule_buf.buffer().bind_storage(kSunSchedule);
    sun.set_uniform("steps", static_cast<int>(steps.distances.size()));
    // The highest height with the march's rounding slack: bilinear rises never exceed it
    // in float (sun_shadow.comp's early exit).
    sun.set_uniform("max_height", static_cast<float>(horizon::march_exit_height_bound(field.heights)));
  }
  const int chunk = static_cast<int>(std::clamp<std::size_t>(invocations / field.width, 1, field.height));
  GpuTimer timer;
  double ms = 0.0;
  for (int r0 = 0; r0 < field.height; r0 += chunk) {
    sun.set_uniform("row_offset", r0);
    sun.set_uniform("chunk_rows", std::min(chunk, field.height - r0));
    {
      ScopedGpuTimer timing(timer);
      sun.dispatch_covering(field.width, std::min(chunk, field.height - r0));
    }
    ms += timer.elapsed_ms();
  }
  return ms;
}

// The sun of sun_shadow.comp as uniforms (the kernel's source, hence the driver's
// compiled-kernel cache entry, is the same for every sun position), and its heading.
std::vector<std::pair<std::string, double>> sun_uniforms(const glm::dvec3& s, horizon::Heading& heading) {
  const double azimuth = sky::azimuth_of(s), elevation = sky::elevation_of(s);
  const double disc_radius = shading::SunShadowOptions{}.radius;
  heading = horizon::heading_from_geographic(azimuth);
  std::vector<std::pair<std::string, double>> uniforms = {{"sun_east", heading.east},
                                                          {"sun_north", heading.north},
                                                          {"sun_elevation", elevation},
                                                          {"sun_sin_az", std::sin(azimuth)},
                                                          {"sun_cos_az", std::cos(azimuth)},
                                                          {"sun_sin_el", std::sin(elevation)},
                                                          {"sun_cos_el", std::cos(elevation)}};
  // sun_shadow.comp's early exit (the march): the slopes of the disc frame's edges
  // y = ±2 (its clip square), widened by 1e-4 relative so float rounding never exits early.
  const double top = elevation + 2.0 * disc_radius, bottom = elevation - 2.0 * disc_radius;
  const double inf = std::numeric_limits<float>::infinity(), near_vertical = std::numbers::pi / 2 - 1e-3;
  uniforms.emplace_back("hidden_slope", top < near_vertical ? std::tan(top) * (1.0 + 1e-4) + 1e-4 : inf);
  uniforms.emplace_back("open_slope",
                        bottom > -near_vertical ? std::tan(bottom) - 1e-4 * std::abs(std::tan(bottom)) - 1e-4 : -inf);
  return uniforms;
}

}  // namespace

bool same_baked_lighting(Product product, const shading::ProductOptions& a, const shading::ProductOptions& b) {
  const bool lit = shading::uses_lighting(product, a);
  if (lit != shading::uses_lighting(product, b)) return false;
  if (!lit) return true;
  if (!a.lighting || !b.lighting) return a.lighting.has_value() == b.lighting.has_value();
  return sun_lit(product, a) == sun_lit(product, b) && (!shading::traits(product).rgb_when_colour || a.lighting->colour == b.lighting->colour) &&
         (a.lighting->sky != nullptr) == (b.lighting->sky != nullptr);
}

bool gpu_supports(Product product, const shading::ProductOptions& options) {
  const auto known = shading::all_product_traits();  // the pipeline has every product
  if (static_cast<std::size_t>(product) >= known.size()) return false;
  // Shaded and irradiance: every ShadedOptions::mode (gpu/shading_setup.h) and both
  // wedge interpolations (ShadedOptions::wedge). Sub-sampling: every s that
  // validate_subsample accepts; the pipeline's constructor throws its message for the others.
  if (!shading::uses_lighting(product, options)) return true;
  // Lit products: the sun's own march (not the exact one), and a lighting to use.
  return options.lighting.has_value() && !options.exact;
}

struct GpuProductPipeline::Impl {
  int azimuths = 0;
  std::optional<ComputeProgram> march;     // horizon_march.comp, or horizon_exact.comp with exact
  // horizon_march.comp for fields whose rows share one spacing (projected grids): no
  // per-step row-spacing fetches (5–10 % of the march on llvmpipe). Compiled at first use.
  std::optional<ComputeProgram> march_one_dx;
  GlslDefines march_defines;
  SweepTextures sweep_textures;  // the sweep's (shading/horizon/horizon_sweep.h)
  bool last_compute_swept = false;  // far_codes() holds the last compute()'s
  std::vector<horizon::Heading> band_headings;
  // horizon_march.comp for a sub-sampled sweep (SWEPT: its pass 0 on the sweep's
  // horizons), [one_dx]. Compiled at first use.
  std::optional<ComputeProgram> swept_march[2];
  const ComputeProgram& swept_march_kernel(const shading::ProductOptions& o, bool one_dx) {
    std::optional<ComputeProgram>& slot = swept_march[one_dx ? 1 : 0];
    if (!slot) {
      GlslDefines d = march_defines;
      add_swept_defines(d.set("SWEPT", 1), o, one_dx);
      const auto compile_start = Clock::now();
      slot.emplace(ComputeProgram::from_embedded("horizon_march.comp", d));
      compile_ms += ms_since(compile_start);
    }
    return *slot;
  }
  // surface_products.comp [cache][swept]: on the march's sigma buffer, or [.][1] on the
  // sweep's far slopes (SWEPT: near steps in the kernel); cache: VisCache (VIS_CACHE,
  // and from the kept visibility, SKY_CACHE 1 keeping the sky irradiance or 2 reading it).
  // Compiled at first use.
  enum VisCache { kNoCache = 0, kKeepVis = 1, kReadVis = 2, kKeepSky = 3, kReadSky = 4 };
  // [cache][0: marched, 1: swept on one row spacing, 2: swept on curved rows (near
  // steps by each row's spacing)].
  // [.][.][0]: a blocked pipeline's kernel without the spheres (BLOCKERS 0), for the
  // texels no sphere's sky bin reaches.
  std::optional<ComputeProgram> products[5][3][2];
  GlslDefines products_defines;
  int blocked = 0;  // BLOCKERS of the products kernels (kReadSky's: 0)
  std::optional<glm::vec3> products_sun_dir;  // lit: the sun's direction (unit, toward it)
  void set_products_sun(const ComputeProgram& p) const {
    if (!products_sun_dir || !p.has_uniform("sun_dir")) return;  // absent when the sun is off (SUN_LIT 0)
    p.set_uniform("sun_dir", products_sun_dir->x, products_sun_dir->y, products_sun_dir->z);
    for (int c = 0; c < channels; ++c) p.set_uniform("sun_dni[" + std::to_string(c) + "]", static_cast<float>(sun_dni[c]));
  }
  const ComputeProgram& products_kernel(const shading::ProductOptions& o, bool swept, bool one_dx,
                                        VisCache cache = kNoCache, bool spheres = true) {
    if (cache >= kReadVis) swept = false;  // no horizons read
    const int kind = swept ? (one_dx ? 1 : 2) : 0;
    spheres = spheres && blocked && cache != kReadSky;
    std::optional<ComputeProgram>& slot = products[cache][kind][spheres ? 1 : 0];
    if (!slot) {
      GlslDefines d = products_defines;
      d.set("SWEPT", swept ? 1 : 0)
          .set("VIS_CACHE", std::min<int>(cache, kReadVis))
          .set("SKY_CACHE", cache == kKeepSky ? 1 : cache == kReadSky ? 2 : 0)
          .set("BLOCKERS", spheres ? 1 : 0)
          .set("VIS_BINDING", kVis)
          .set("KEPT_HORIZON_BINDING", kKeptHorizons)
          .set("KEPT_SKY_BINDING", kKeptSky);
      if (swept) add_swept_defines(d.set("RAY_TEXTURES", 1), o, one_dx);
      const auto compile_start = Clock::now();
      slot.emplace(ComputeProgram::from_embedded("surface_products.comp", d));
      compile_ms += ms_since(compile_start);
      set_products_sun(*slot);
    }
    return *slot;
  }
  // The kept visibility: SH_COEFFS floats per texel, coefficient-major, and in a blocked
  // pipeline the AZIMUTHS floored horizon slopes, band-major, for the field revision
  // they were computed from (vis_valid).
  Buffer vis, kept_horizons;
  bool keep_vis = false, vis_valid = false;
  std::uint64_t vis_field_id = 0, vis_revision = 0;
  // Which kept texels are current for vis_revision, and the texels per compute() that
  // catch up after an edit (0: the edit recomputes all).
  VisibilityRefresh refresh;
  std::size_t refresh_budget = 0;
  // The kept sky irradiance (lit products, keep_sky_irradiance): CHANNELS floats per
  // texel, channel-major, from the kept visibility of (sky_field_id, sky_revision) under
  // the sky model sky_model (held, so that its address is not another sky's later).
  Buffer kept_sky;
  bool keep_sky = false, sky_valid = false;
  std::uint64_t sky_field_id = 0, sky_revision = 0;
  std::shared_ptr<const sky::SkyModel> sky_model;
  int vis_rows = 0;
  int frames = 0;  // compute() calls since the visibility was last dropped
  double compile_ms = 0.0;  // kernels compiled since the last compute() began
  Buffer device_out;        // compute_on_gpu's bands
  // What device_out was computed from, so that a compute_on_gpu() under the same lighting
  // (lighting_serial, bumped by each set_lighting() that changes it) on the same field
  // revision with the sky kept shades again only the texels a sphere reaches, the last
  // frame's or this one's (set_partial_frames). terrain_shadow: that frame's sun shadow
  // before the spheres' pass.
  bool partial_frames = true;
  std::uint64_t lighting_serial = 0;
  struct LastFrame {
    bool valid = false;
    std::uint64_t field_id = 0, revision = 0, lighting = 0;
  } last_frame;
  Buffer terrain_shadow;
  std::optional<std::vector<terrain::PixelRect>> changed;  // last_changed()
  // sun_shadow.comp: shadow, and lit products with a sun, by how it finds the sun's
  // horizon (SUN_SWEPT, SUN_KEPT). Compiled at first use.
  enum SunVariant : int { kSunMarch, kSunSweep, kSunSweepAndKeep, kSunReadKept, kSunReadKeptList, kSunVariants };
  std::optional<ComputeProgram> sun[kSunVariants];
  GlslDefines sun_defines;
  horizon::Heading sun_heading;
  std::vector<std::pair<std::string, double>> sun_uniforms;  // float uniforms, when active
  const ComputeProgram& sun_kernel(SunVariant v) {
    if (!sun[v]) {
      GlslDefines d = sun_defines;
      d.set("SUN_SWEPT", v == kSunMarch ? 0 : 1)
          .set("SUN_KEPT", v == kSunSweepAndKeep ? 2 : v == kSunReadKept || v == kSunReadKeptList ? 1 : 0)
          .set("SUN_KEPT_BINDING", Binding::kSunKept)
          .set("SUN_LIST", v == kSunReadKeptList ? 1 : 0)
          .set("SUN_LIST_BINDING", Binding::kSunList);
      const auto compile_start = Clock::now();
      sun[v].emplace(ComputeProgram::from_embedded("sun_shadow.comp", d));
      compile_ms += ms_since(compile_start);
      set_sun(*sun[v]);
    }
    return *sun[v];
  }
  void set_sun(const ComputeProgram& p) const {
    for (const auto& [name, value] : sun_uniforms)
      if (p.has_uniform(name)) p.set_uniform(name, static_cast<float>(value));
  }
  // set_sweeps_on_host; unset: on a software rasterizer (asked at first use, in the context).
  std::optional<bool> sweeps_on_host;
  bool host_sweeps() {
    if (!sweeps_on_host) sweeps_on_host = software_renderer();
    return *sweeps_on_host;
  }
  // horizon_sweep.comp for the sky's march options (sun: false) or the sun's (their near
  // steps and lines), compiled at first use; null where the host sweeps (sweep_pass).
  std::optional<ComputeProgram> sweeps[2];
  const ComputeProgram* sweep_kernel(const shading::ProductOptions& o, bool sun) {
    if (host_sweeps()) return nullptr;
    if (!sweeps[sun]) {
      const horizon::MarchOptions m = sun ? shading::sun_shadow_options(o).march : o.march;
      GlslDefines d = common_defines(azimuths, o);
      d.set("RAY_TEXTURES", 1)
          .set("NEAR_STEPS", m.sweep_near_steps)
          .set("LINES_PER_TEXEL", m.sweep_lines)
          .set("SWEEP_LOCAL_SIZE", kSweepLocalSize)
          .set("HULL_IMAGE_UNIT", kHullImageUnit)
          .set("FAR_IMAGE_UNIT", kFarImageUnit)
          .set("HELD_IMAGE_UNIT", kHeldImageUnit)
          .set("FAR_HULL_IMAGE_UNIT", kFarHullImageUnit)
          .set("HIDDEN_IMAGE_UNIT", kHiddenImageUnit)
          .set("GAMMA_BINDING", kSweepGamma)
          .set("ROW_DX_D_BINDING", kSweepRowDx)
          .set("DUE_EAST_SLOPE", horizon::kDueEastSlope);
      add_far_code_defines(d);
      const auto compile_start = Clock::now();
      sweeps[sun].emplace(ComputeProgram::from_embedded("horizon_sweep.comp", d));
      compile_ms += ms_since(compile_start);
    }
    return &*sweeps[sun];
  }
  // Stage 0: the sun's shadow into `shadow`, marched or swept (shading::sun_sweeps) as
  // the reference does; returns the GPU time (ms) and sets t's uploaded bytes,
  // sun_far_reused and sun_texels. Needs the resident field bound.
  double sun_stage(const terrain::HeightField& f, const shading::ProductOptions& o, std::size_t invocations,
                   Buffer& shadow, GpuPipelineTimings& t) {
    std::size_t& uploaded = t.uploaded_bytes;
    const bool swept = shading::sun_sweeps(f, shading::sun_shadow_options(o));
    const TextureArray* far = nullptr;
    // The resident heights and row spacings as buffer textures, for the sweep and the pass.
    const BufferTexture heights_tex(field.heights()), row_dx_tex(field.row_dx());
    heights_tex.bind_sampler(kHeights);
    row_dx_tex.bind_sampler(kRowDx);
    double sweep_ms = 0.0;
    // The swept far slopes hold below the floor only for a sun at most half the floor's
    // margin lower (shading::sun_sweep_floor).
    const bool reuse_far = swept && sun_far_valid && sun_far_field_id == f.id.value() && sun_far_revision == f.revision &&
                           horizon::heading_angle(sun_far_heading, sun_heading) <= sun_heading_tolerance &&
                           sky::elevation_of(o.lighting->sun.direction) >= sun_far_elevation - 0.5 * shading::kSunFloorMargin;
    t.sun_far_reused = reuse_far;
    SunVariant variant = swept ? kSunSweep : kSunMarch;
    if (reuse_far) {
      far = &sweep_textures.sun_far;
      variant = kSunReadKept;
      // How far the sun moved from the swept one, with slack for the kernels' float
      // rounding of the lines' distances (~1e-7 rad; the disc's radius is 4.6e-3 rad).
      const double moved = sky::angle_between(sun_far_direction, o.lighting->sun.direction) + kSunMovedSlack;
      if (moved <= sun_list_angle && !sun_list_made) make_sun_list(f);
      if (moved <= sun_list_angle && sun_list_count <= kMaxSunList) {
        sun_kept.bind_storage(Binding::kSunKept);
        t.sun_texels = static_cast<std::size_t>(sun_list_count);
        return sun_list_pass(f, moved, shadow);
      }
      sun_kernel(kSunReadKept).set_uniform("sun_moved", static_cast<float>(moved));
    } else if (swept) {
      GpuTimer timer;
      {
        ScopedGpuTimer timing(timer);
        far = &sun_far_slopes(sweep_kernel(o, true), f, o, sun_heading, sweep_textures);
      }
      sweep_ms = timer.elapsed_ms();
      sun_far_valid = sun_heading_tolerance > 0.0;
      sun_far_field_id = f.id.value();
      sun_far_revision = f.revision;
      sun_far_heading = sun_heading;
      sun_far_direction = o.lighting->sun.direction;
      sun_far_elevation = sky::elevation_of(o.lighting->sun.direction);
      const std::size_t bytes = 2 * f.size() * sizeof(float);  // elevations, then margins
      if (sun_far_valid) try {
          check_storage_size(bytes, "GPU pipeline: the sun's kept horizon");
        } catch (const std::runtime_error&) {
          sun_far_valid = false;  // over one storage buffer: every frame sweeps
        }
      if (sun_far_valid) {
        if (sun_kept.size_bytes() != bytes) {
          sun_kept = Buffer();
          sun_kept = Buffer(bytes);
        }
        variant = kSunSweepAndKeep;
      }
    }
    if (variant == kSunSweepAndKeep || variant == kSunReadKept) sun_kept.bind_storage(Binding::kSunKept);
    t.sun_texels = f.size();
    const double pass_ms = sun_pass(sun_kernel(variant), f, o, invocations, sun_schedule, uploaded, shadow, far);
    if (variant == kSunSweepAndKeep) keep_sun_list(shadow);
    return sweep_ms + pass_ms;
  }
  // The swept frame's shadow and, made at the first later frame that needs them, the
  // texels whose certainty margin (sun_shadow.comp) is under sun_list_angle: a later
  // frame whose sun moved less than that angle from the swept one copies the shadow and
  // shades the listed texels only (llvmpipe pays for every invocation a dispatch covers,
  // even those that return at once). A series whose every frame sweeps makes no list.
  static constexpr double kSunMovedSlack = 1e-5;  // rad: the kernels' float rounding of the lines' distances is ~1e-7
  static constexpr int kMaxSunList = 65535 * kLocalSize * kLocalSize;  // one dispatch's groups
  Buffer sun_base, sun_list;
  int sun_list_count = 0;
  bool sun_list_made = false;
  double sun_list_angle = 0.0;  // 0: no list
  void keep_sun_list(const Buffer& shadow) {
    sun_list_angle = 2.0 * sun_heading_tolerance;  // the heading's and some more for the elevation
    sun_list_made = false;
    sun_base.assign(shadow);
  }
  void make_sun_list(const terrain::HeightField& f) {
    std::vector<float> margins(f.size());
    sun_kept.download(margins.data(), f.size() * sizeof(float), f.size() * sizeof(float));
    std::vector<std::uint32_t> list;
    for (std::size_t t = 0; t < margins.size(); ++t)
      if (f.valid[t] && !(std::abs(margins[t]) > sun_list_angle)) list.push_back(static_cast<std::uint32_t>(t));
    sun_list_count = static_cast<int>(std::min<std::size_t>(list.size(), kMaxSunList + std::size_t{1}));
    if (list.empty()) list.push_back(0);  // GL wants non-empty buffers bound
    sun_list = Buffer::from(std::span<const std::uint32_t>(list));
    sun_list_made = true;
  }
  double sun_list_pass(const terrain::HeightField& f, double moved, Buffer& shadow) {
    const auto start = Clock::now();
    shadow = sun_base.copy();
    shadow.bind_storage(kShadow);
    sun_list.bind_storage(Binding::kSunList);
    const ComputeProgram& kernel = sun_kernel(kSunReadKeptList);
    set_grid_uniforms(kernel, f);
    kernel.set_uniform("sun_moved", static_cast<float>(moved));
    kernel.set_uniform("list_count", sun_list_count);
    const int groups = (sun_list_count + kLocalSize * kLocalSize - 1) / (kLocalSize * kLocalSize);
    if (groups > 0) kernel.dispatch_covering(groups * kLocalSize, kLocalSize);  // one row of groups
    glFinish();  // wall clock: llvmpipe's timer queries report ~0 for compute
    return ms_since(start);
  }
  // The sun's far slopes kept for later compute()s (set_sun_heading_tolerance): valid for
  // one field revision and the heading they were swept along. A later frame reads each
  // texel's whole horizon elevation along that heading from sun_kept (its near steps
  // included: they move least with the heading, 0.05° shifts a step 1/1000 of a texel),
  // and where the sun moved less than the texel's certainty margin (sun_shadow.comp) the
  // swept frame's 0 or 1 without the disc's pass.
  Buffer sun_kept;
  double sun_heading_tolerance = 0.0;
  bool sun_far_valid = false;
  std::uint64_t sun_far_field_id = 0, sun_far_revision = 0;
  horizon::Heading sun_far_heading;
  glm::dvec3 sun_far_direction{0.0, 0.0, 1.0};  // the sun they were swept for
  double sun_far_elevation = 0.0;               // its elevation (rad)
  std::optional<GpuPyramid> pyramid;       // the multi-resolution march's pyramid, built on the GPU
  std::uint64_t pyramid_field_id = 0, pyramid_revision = 0;  // the field it was built from
  // The pyramid of the resident field `f`: updated in place after one edit of the field it
  // was built from (updatable when edits refresh incrementally), else built; returns the
  // wall milliseconds it took (0 when it was current).
  double sync_pyramid(const terrain::HeightField& f, const horizon::MarchOptions& m, std::size_t& uploaded) {
    if (pyramid_field_id == f.id.value() && pyramid_revision == f.revision) return 0.0;
    const auto start = Clock::now();
    if (pyramid->updatable() && pyramid_field_id == f.id.value() && f.one_edit_since(pyramid_revision)) {
      pyramid->update(field.heights(), f.last_dirty);
    } else {
      uploaded += pyramid->build(field.heights(), f.width, f.height, horizon::march_pyramid_options(m),
                                 !bilinear_levels(m), refresh_budget > 0);
    }
    pyramid_field_id = f.id.value();
    pyramid_revision = f.revision;
    glFinish();  // wall clock: llvmpipe's timer queries report ~0 for compute
    return ms_since(start);
  }
  // Resident between compute() calls (gpu/resident_field.h): an edited field re-uploads
  // only its changed rows; the schedules only when they change.
  ResidentField field;
  ResidentTable schedule, sun_schedule;
  Buffer no_coeffs;  // bound in place of the pyramid without use_pyramid
  Buffer headings;
  // Sphere blockers (present in blocked pipelines only): the frame's spheres and bins,
  // and blocker_sun.comp, which multiplies the sun's shadow by what they leave.
  std::optional<GpuBlockers> blockers;
  std::vector<blockers::Sphere> spheres;  // this frame's (set_spheres)
  std::optional<ComputeProgram> blocker_sun;
  glm::vec3 blocker_sun_dir{0.0f, 0.0f, 1.0f};
  // The blockers' pass over the shadow in `shadow` (bound at kShadow by sun_pass).
  double blocker_sun_stage(const terrain::HeightField& f) const {
    if (!blocker_sun) return 0.0;
    blockers->bind(*blocker_sun);
    set_grid_uniforms(*blocker_sun, f);
    blocker_sun->set_uniform("sun_dir", blocker_sun_dir.x, blocker_sun_dir.y, blocker_sun_dir.z);
    GpuTimer timer;
    double ms = 0.0;
    for (const terrain::PixelRect& r : blockers->sun_rects()) {  // the texels the spheres' sun bins reach
      blocker_sun->set_uniform("origin", r.x0, r.y0);
      blocker_sun->set_uniform("extent", r.width, r.height);
      {
        ScopedGpuTimer timing(timer);
        blocker_sun->dispatch_covering(r.width, r.height);
      }
      ms += timer.elapsed_ms();
    }
    return ms;
  }
  Buffer table, gamma;    // shaded and irradiance only (gpu/shading_setup.h)
  // `table` (and its view) from ShadingSetup::sky, in place when the size stays.
  void upload_sky_tables(const std::vector<float>& sky, shading::ShadingMode mode);
  BufferTexture gamma_tex;  // Γ's view (sh_product.glsl)
  BufferTexture table_tex;  // the surface kernel's view (table mode)
  int channels = 1;               // output bands of shaded/irradiance
  std::vector<double> sun_dni;    // lit: the sun's DNI per output channel
  double display_per_irradiance = 0.0;  // lit shaded: the tone map's factor
};

GpuProductPipeline::GpuProductPipeline(Product product, const shading::ProductOptions& options, bool blocked)
    : mProduct(product), mOptions(options), mImpl(new Impl) {
  validate_options(product, options);
  Impl& k = *mImpl;
  blocked = blocked && shading::traits(product).blocked;
  if (blocked)
    if (const auto why = gpu_lacks_blockers(product, options)) throw std::invalid_argument(*why);
  const bool lit = shading::uses_lighting(product, options);
  const bool sky_vis = sh_visibility(product, blocked);
  if (sun_lit(product, options) || shading::traits(product).sun_only) {
    // Sun shadow kernel: the sun's angles as compute_product takes them from the lighting.
    const double disc_radius = shading::SunShadowOptions{}.radius;
    GlslDefines sun;
    sun.set("LOCAL_SIZE_X", kLocalSize)
        .set("LOCAL_SIZE_Y", kLocalSize)
        .set("PI", std::numbers::pi)
        .set("HALF_PI", std::numbers::pi / 2)
        .set("INV_TWO_R_EFF", options.march.curvature.drop_per_square_metre())
        .set("HEIGHTS_BINDING", kHeights)
        .set("ROW_DX_BINDING", kRowDx)
        .set("VALID_BINDING", kValid)
        .set("SCHEDULE_BINDING", kSunSchedule)
        .set("SHADOW_BINDING", kShadow)
        .set("DISC_RADIUS", disc_radius)
        .set("NEAR_STEPS", shading::sun_shadow_options(options).march.sweep_near_steps)
        .set("FAR_BINDING", kFar)
        .set("RAY_TEXTURES", 1);  // heights by buffer textures: vector gathers on llvmpipe (gpu/buffers.h)
    add_far_code_defines(sun);
    k.sun_defines = sun;
    k.sun_uniforms = sun_uniforms(options.lighting->sun.direction, k.sun_heading);
    k.sun_kernel(Impl::kSunMarch);  // the march's variant now; the sweep's at its first field
    if (blocked) {
      GlslDefines d;
      d.set("LOCAL_SIZE_X", kLocalSize)
          .set("LOCAL_SIZE_Y", kLocalSize)
          .set("PI", std::numbers::pi)
          .set("HEIGHTS_BINDING", kHeights)
          .set("ROW_DX_BINDING", kRowDx)
          .set("SHADOW_BINDING", kShadow);
      add_blocker_defines(options, kBlockerBindings, false, d);
      k.blocker_sun.emplace(ComputeProgram::from_embedded("blocker_sun.comp", d));
      k.blocker_sun_dir = glm::vec3(options.lighting->sun.direction);
    }
  }
  if (blocked) k.blockers.emplace(options, kBlockerBindings, product != Product::Shadow);
  if (shading::traits(product).sun_only) return;  // the sun kernel alone
  k.azimuths = horizon_bands(product, options);
  k.band_headings = band_headings(product, k.azimuths, blocked);
  std::vector<float> headings;
  for (const horizon::Heading& u : k.band_headings) {
    headings.push_back(static_cast<float>(u.east));
    headings.push_back(static_cast<float>(u.north));
  }
  k.headings = Buffer::from(std::span<const float>(headings));

  // March kernel.
  GlslDefines march = common_defines(k.azimuths, options);
  if (options.exact) {
    march.set("STEP_TEXELS", options.exact_options.step_texels);
    k.march.emplace(ComputeProgram::from_embedded("horizon_exact.comp", march));
  } else {
    march.set("SMOOTH_MAX", options.march.smooth_max ? 1 : 0)
        .set("USE_PYRAMID", options.march.use_pyramid ? 1 : 0)
        .set("LEVEL_BILINEAR", bilinear_levels(options.march) ? 1 : 0)
        .set("SCHEDULE_BINDING", kSchedule)
        .set("MAX_STEPS", kMaxMarchSteps)
        .set("COEFFS_BINDING", kCoeffs)
        .set("RAY_TEXTURES", 1)  // heights, row spacing, coefficients: buffer textures at those units
        .set("SUBSAMPLE", options.subsample)
        .set("EXIT_SLACK", horizon::MarchExitSlack::angle)  // early exit (horizon_march.h)
        .set("EXIT_TAIL", options.march.smooth_max ? horizon::MarchExitSlack::smooth_window - 1 : 0)
        .set("COARSE_SIGMA_BINDING", kCoarseSigma)
        .set("VALID_BINDING", kValid);
    k.march.emplace(ComputeProgram::from_embedded("horizon_march.comp", march));
    k.march_defines = march;
    if (options.march.use_pyramid) {
      k.pyramid.emplace();
    } else {  // unused by the kernel; GL wants non-empty buffers bound
      k.no_coeffs = Buffer(sizeof(float));
    }
  }

  // Product kernel.
  GlslDefines prod = common_defines(k.azimuths, options);
  prod.set("PRODUCT_HORIZON", static_cast<int>(Product::Horizon))
      .set("PRODUCT_SVF", static_cast<int>(Product::Svf))
      .set("PRODUCT_SKYVIEW", static_cast<int>(Product::Skyview))
      .set("PRODUCT_SHADED", static_cast<int>(Product::Shaded))
      .set("PRODUCT_IRRADIANCE", static_cast<int>(Product::Irradiance))
      .set("PRODUCT", static_cast<int>(product))
      .set("LIT", lit ? 1 : 0)
      .set("SUBSAMPLE", options.subsample)
      .set("COARSE_SIGMA_UNIT", kCoarseSigma)
      .set("EXACT_MARCH", options.exact ? 1 : 0)
      .set("PI", std::numbers::pi)
      .set("HALF_PI", std::numbers::pi / 2)
      .set("TWO_PI", horizon::kTwoPi)
      .set("VALID_BINDING", kValid)
      .set("OUTPUT_BINDING", kOutput);
  if (options.exact) prod.set("STEP_TEXELS", options.exact_options.step_texels);
  if (sky_vis) {
    const shading::ShadedOptions& s = options.shaded;
    const sh::WedgeOperator& op = sh::wedge_operator(s.sh_order, s.nlp_order, k.azimuths, s.wedge);
    // The sky shading as the reference sets it up; gpu_products_test /
    // gpu_lighting_test / gpu_shading_modes_test fail if the two diverge. A blocked
    // skyview shades its change with the uniform sky's table, as the reference does.
    shading::ProductOptions shading_options = options;
    if (!needs_visibility(product)) shading_options.shaded.mode = shading::ShadingMode::SkyBrdfTable;
    const Product shading_product = needs_visibility(product) ? product : Product::Shaded;
    ShadingSetup shading = shading_setup(shading_product, shading_options, kTable, kGammaUnit, prod);
    if (blocked) add_blocker_shading(shading_options, kGammaUnit, shading, prod);
    k.channels = shading.channels;
    k.sun_dni = shading.sun_dni;
    if (lit) {
      k.display_per_irradiance = shading::shaded_display_scale(s, *options.lighting);
      prod.set("SUN_LIT", sun_lit(product, options) ? 1 : 0).set("SHADOW_BINDING", kShadow);
    }
    std::vector<double> occlusion_factors(s.nlp_order, 0.0);
    for (int l = 1; l < s.nlp_order; ++l) occlusion_factors[l] = sh::nlp_norm(l) / (static_cast<double>(l) * (l + 1));
    prod.set("SH_ORDER", s.sh_order)
        .set("SH_COEFFS", op.rows())
        .set("NLP_ORDER", s.nlp_order)
        .set("NLP_V0_SCALE", sh::nlp_norm(0))
        .set_literal("NLP_OCCLUSION_FACTORS", glsl_float_array_literal(occlusion_factors))
        // Constants, not a buffer: the compiler folds G's zeros and needs no gathers.
        .set_literal("WEDGE_FOURIER", glsl_float_array_literal(wedge_fourier_matrix(op)));
    k.vis_rows = op.rows();
    k.table = Buffer::from(std::span<const float>(shading.sky));
    k.gamma = Buffer::from(std::span<const float>(shading.gamma));
    k.gamma_tex = BufferTexture(k.gamma, TextureFormat::RGBA32F);
    if (shading_options.shaded.mode == shading::ShadingMode::SkyBrdfTable)
      k.table_tex = BufferTexture(k.table, TextureFormat::RGBA32F);
  }
  k.blocked = blocked ? 1 : 0;
  if (blocked) add_blocker_defines(options, kBlockerBindings, true, prod);
  k.products_defines = prod;
  if (lit) k.products_sun_dir = glm::vec3(options.lighting->sun.direction);
  // The variant the options will most likely use now (compile time is reported apart);
  // the other at its first field.
  k.products_kernel(options, options.march.method == horizon::HorizonMethod::Sweep && !options.exact &&
                                 options.subsample == 1, true);
}

GpuProductPipeline::~GpuProductPipeline() = default;

void GpuProductPipeline::set_lighting(const shading::Lighting& lighting) {
  shading::ProductOptions next = mOptions;
  next.lighting = lighting;
  if (!shading::uses_lighting(mProduct, mOptions) || !same_baked_lighting(mProduct, mOptions, next))
    throw std::logic_error("GpuProductPipeline::set_lighting: the lighting differs in what the kernels bake in");
  shading::validate(lighting);
  const shading::Lighting& now = *mOptions.lighting;
  const std::shared_ptr<const sky::SkyModel> now_sky = now.sky;
  // The same sky object, sun and tone map: the uniforms and tables are set already (the
  // first frame's lighting is the constructor's; the bench repeats one).
  if (lighting.sky == now.sky && lighting.sun.direction == now.sun.direction && lighting.sun.dni == now.sun.dni &&
      lighting.reference_irradiance == now.reference_irradiance)
    return;
  mOptions = std::move(next);
  Impl& k = *mImpl;
  ++k.lighting_serial;
  if (k.sun[Impl::kSunMarch]) {  // made with the pipeline when it has a sun pass
    k.sun_uniforms = sun_uniforms(lighting.sun.direction, k.sun_heading);
    for (const auto& p : k.sun)
      if (p) k.set_sun(*p);
  }
  k.blocker_sun_dir = glm::vec3(lighting.sun.direction);
  if (!needs_visibility(mProduct)) return;
  k.display_per_irradiance = shading::shaded_display_scale(mOptions.shaded, lighting);
  k.products_sun_dir = glm::vec3(lighting.sun.direction);
  // The sky's tables depend on the sky model alone: the same one keeps them.
  if (lighting.sky == now_sky) {
    k.sun_dni = channel_dni(lighting, shading::rgb_bands(mProduct, mOptions));
  } else {
    GlslDefines unused;  // the kernels' defines are the same (same_baked_lighting)
    const ShadingSetup shading = shading_setup(mProduct, mOptions, kTable, kGammaUnit, unused);
    k.sun_dni = shading.sun_dni;
    k.upload_sky_tables(shading.sky, mOptions.shaded.mode);
  }
  for (const auto& by_cache : k.products)
    for (const auto& by_kind : by_cache)
      for (const auto& p : by_kind)
        if (p) k.set_products_sun(*p);
}

void GpuProductPipeline::Impl::upload_sky_tables(const std::vector<float>& sky, shading::ShadingMode mode) {
  if (table.size_bytes() == sky.size() * sizeof(float)) {
    table.upload(sky.data(), table.size_bytes());
  } else {
    table_tex = BufferTexture();
    table = Buffer::from(std::span<const float>(sky));
    if (mode == shading::ShadingMode::SkyBrdfTable) table_tex = BufferTexture(table, TextureFormat::RGBA32F);
  }
}

void GpuProductPipeline::set_tone_map(double exposure, shading::ToneCurve tone) {
  if (!(exposure > 0.0)) throw std::invalid_argument("shaded: exposure must be > 0");
  mOptions.shaded.exposure = exposure;
  mOptions.shaded.tone = tone;
  if (shading::uses_lighting(mProduct, mOptions))
    mImpl->display_per_irradiance = shading::shaded_display_scale(mOptions.shaded, *mOptions.lighting);
}

void GpuProductPipeline::set_region(const terrain::PixelRect& region) {
  if (region == mOptions.march.region) return;
  mOptions.march.region = region;
  drop_visibility();  // computed for another region
}

void GpuProductPipeline::keep_visibility(bool keep) { mImpl->keep_vis = keep; }

void GpuProductPipeline::set_refresh_budget(std::size_t texels_per_frame) { mImpl->refresh_budget = texels_per_frame; }

void GpuProductPipeline::set_sun_heading_tolerance(double radians) {
  if (!(radians >= 0.0) || radians > kMaxSunHeadingTolerance)
    throw std::invalid_argument("sun heading tolerance must be within 0 … " + std::to_string(kMaxSunHeadingTolerance) + " rad");
  mImpl->sun_heading_tolerance = radians;
  if (radians == 0.0) {  // nothing is kept any more: neither the slopes nor their elevations' memory
    mImpl->sun_far_valid = false;
    mImpl->sun_kept = Buffer();
    mImpl->sun_base = Buffer();
    mImpl->sun_list = Buffer();
  }
}

void GpuProductPipeline::keep_sky_irradiance(bool keep) {
  mImpl->keep_sky = keep;
  if (!keep) {
    mImpl->sky_valid = false;
    mImpl->kept_sky = Buffer();
  }
}

void GpuProductPipeline::set_spheres(std::span<const blockers::Sphere> spheres) {
  if (!mImpl->blockers) throw std::logic_error("GpuProductPipeline::set_spheres: the pipeline was built without blockers");
  mImpl->spheres.assign(spheres.begin(), spheres.end());
}

void GpuProductPipeline::drop_visibility() {
  Impl& k = *mImpl;
  k.sky_valid = false;
  k.kept_sky = Buffer();
  k.vis = Buffer();
  k.kept_horizons = Buffer();
  k.vis_valid = false;
  k.sun_far_valid = false;
  k.frames = 0;
}

void GpuProductPipeline::set_sweeps_on_host(bool on_host) { mImpl->sweeps_on_host = on_host; }

void GpuProductPipeline::set_partial_frames(bool partial) {
  mImpl->partial_frames = partial;
  if (!partial) mImpl->terrain_shadow = Buffer();
}

const std::optional<std::vector<terrain::PixelRect>>& GpuProductPipeline::last_changed() const { return mImpl->changed; }

bool GpuProductPipeline::sweeps_on_host() const { return mImpl->host_sweeps(); }

std::vector<std::uint16_t> GpuProductPipeline::far_codes() const {
  const Impl& k = *mImpl;
  if (!k.last_compute_swept) return {};
  return k.sweep_textures.far.download();
}

shading::ProductBands GpuProductPipeline::compute(const terrain::HeightField& field,
                                                  const shading::ProgressCallback& progress,
                                                  GpuPipelineTimings* timings) const {
  return run(field, progress, timings, false);
}

const Buffer& GpuProductPipeline::compute_on_gpu(const terrain::HeightField& field,
                                                 const shading::ProgressCallback& progress,
                                                 GpuPipelineTimings* timings) const {
  run(field, progress, timings, true);
  return mImpl->device_out;
}

double GpuProductPipeline::display_scale() const {
  if (!shading::traits(mProduct).eight_bit) return 1.0;
  if (shading::uses_lighting(mProduct, mOptions)) return mImpl->display_per_irradiance;
  return mOptions.shaded.albedo * mOptions.shaded.exposure;
}

shading::ProductBands GpuProductPipeline::run(const terrain::HeightField& field, const shading::ProgressCallback& progress,
                                              GpuPipelineTimings* timings, bool on_gpu) const {
  if (field.width < 1 || field.height < 1) throw std::invalid_argument("compute_product: empty height field");
  const auto start = Clock::now();
  GpuPipelineTimings t;
  Impl& k = *mImpl;  // compute() keeps the field resident in it (single-threaded, as GL is)
  k.compile_ms = 0.0;
  k.changed.reset();
  const Impl::LastFrame last_frame = std::exchange(k.last_frame, {});

  const int w = field.width, h = field.height, bands = k.azimuths;
  const int out_bands = shading::band_count(mProduct, mOptions);
  const std::size_t texels = field.size();

  if (auto night = shading::night_shadow(mProduct, {mOptions.lighting, {}, std::nullopt}, field)) {
    if (on_gpu) k.device_out = Buffer::from(std::span<const float>(night->data));
    if (progress) progress(1.0);
    t.frame_ms = ms_since(start);
    if (timings) *timings = t;
    return std::move(*night);
  }
  if (shading::traits(mProduct).sun_only) {  // the sun pass alone
    const auto upload_start = Clock::now();
    t.uploaded_bytes = k.field.sync(field);
    k.field.heights().bind_storage(kHeights);
    k.field.row_dx().bind_storage(kRowDx);
    k.field.valid().bind_storage(kValid);
    t.upload_ms = ms_since(upload_start);
    if (k.blockers) t.uploaded_bytes += k.blockers->upload(field, k.spheres, mOptions);
    Buffer shadow;
    t.sun_ms = k.sun_stage(field, mOptions, mInvocationsPerDispatch, shadow, t);
    t.sun_ms += k.blocker_sun_stage(field);
    shading::ProductBands out{w, h, 1, {}, {std::string(shading::product_name(mProduct))}};
    if (on_gpu) {
      k.device_out = std::move(shadow);
    } else {
      out.data.resize(texels);
      shadow.download(out.data.data(), texels * sizeof(float));
    }
    throw_on_gl_error("GpuProductPipeline::compute (shadow)");
    if (progress) progress(1.0);
    t.compile_ms = k.compile_ms;
    t.frame_ms = ms_since(start);
    if (timings) *timings = t;
    return out;
  }

  // The field: resident between calls; an edited one re-uploads its changed rows only.
  const auto upload_start = Clock::now();
  t.uploaded_bytes = k.field.sync(field);
  t.upload_ms = ms_since(upload_start);

  // The visibility an earlier compute() kept for this field revision (stages 1–2 and the
  // visibility are skipped), or (keeping) this one's, for the computes after it.
  const bool vis_product = needs_visibility(mProduct);
  // A blocked frame keeps the floored horizon slopes too (the spheres' horizon cull).
  const bool kept_field = vis_product && k.vis_valid && k.vis_field_id == field.id.value();
  // Incremental: the texels to recompute into the kept visibility, the rest read from it.
  std::vector<terrain::PixelRect> refresh_rects;
  if (kept_field && mOptions.subsample == 1) {
    if (k.refresh_budget > 0 && field.one_edit_since(k.vis_revision)) {
      refresh_rects = {k.refresh.edit(field.last_dirty, kRefreshMarginTexels)};
    } else if (field.revision == k.vis_revision && !k.refresh.complete()) {
      refresh_rects = k.refresh.refine(k.refresh_budget > 0 ? k.refresh_budget : texels);
    }
  }
  const bool incremental = !refresh_rects.empty();
  const bool reuse = kept_field && k.vis_revision == field.revision && !incremental;
  bool keep = vis_product && !reuse && (k.keep_vis || k.frames > 0 || incremental);
  if (keep) {
    const std::size_t vis_bytes = texels * static_cast<std::size_t>(k.vis_rows) * sizeof(float);
    const std::size_t horizon_bytes = k.blockers ? texels * static_cast<std::size_t>(bands) * sizeof(float) : 0;
    k.vis_valid = false;
    try {
      check_storage_size(vis_bytes, "GPU pipeline: the kept visibility");
      check_storage_size(horizon_bytes, "GPU pipeline: the kept horizons");
      if (k.vis.size_bytes() != vis_bytes) {
        k.vis = Buffer();
        k.vis = Buffer(vis_bytes);
      }
      if (horizon_bytes != 0 && k.kept_horizons.size_bytes() != horizon_bytes) {
        k.kept_horizons = Buffer();
        k.kept_horizons = Buffer(horizon_bytes);
      }
    } catch (const std::runtime_error&) {
      keep = false;  // over one storage buffer: every compute() does all its work
    }
  }
  t.horizons_reused = reuse;
  // A reused visibility's frame reads the kept sky irradiance under the same sky model
  // (kReadSky), else computes it and keeps it (kKeepSky).
  Impl::VisCache read_cache = Impl::kReadVis;
  if (!reuse) k.sky_valid = false;
  if (reuse && k.keep_sky && shading::uses_lighting(mProduct, mOptions)) {
    if (k.sky_valid && k.sky_field_id == field.id.value() && k.sky_revision == field.revision &&
        k.sky_model == mOptions.lighting->sky) {
      read_cache = Impl::kReadSky;
    } else {
      const std::size_t sky_bytes = texels * static_cast<std::size_t>(k.channels) * sizeof(float);
      try {
        check_storage_size(sky_bytes, "GPU pipeline: the kept sky irradiance");
        if (k.kept_sky.size_bytes() != sky_bytes) {
          k.kept_sky = Buffer();
          k.kept_sky = Buffer(sky_bytes);
        }
        read_cache = Impl::kKeepSky;
      } catch (const std::runtime_error&) {  // over one storage buffer: computed every frame
      }
    }
  }
  t.sky_reused = read_cache == Impl::kReadSky;
  // The last frame left on the GPU, under this lighting, on this field revision, with the
  // sky irradiance kept: only the texels a sphere reaches, then or now, can change.
  const bool partial = on_gpu && k.partial_frames && read_cache == Impl::kReadSky && mOptions.subsample == 1 &&
                       last_frame.valid && last_frame.field_id == field.id.value() &&
                       last_frame.revision == field.revision && last_frame.lighting == k.lighting_serial &&
                       k.device_out.size_bytes() == texels * out_bands * sizeof(float) &&
                       (!k.blockers || k.terrain_shadow.size_bytes() == texels * sizeof(float));
  t.shading_kept = partial;
  t.sun_far_reused = partial;  // the sun's horizon kept with its whole shadow

  // Stage 1: the marcher's step schedule (C++) and the height pyramid, built on the GPU
  // from the resident heights (rebuilt whole on every call; its tables stay resident).
  int steps_count = 0;
  double first_distance = 0.0;
  float z_bound = std::numeric_limits<float>::infinity();  // the march's early exit (horizon_march.h)
  // As the reference decides; an incremental refresh marches (the sweep is not local).
  const bool sweep = !reuse && !incremental && shading::uses_sweep(field, mOptions);
  if (!reuse) k.last_compute_swept = sweep;
  // A swept field refreshed after an edit marches: its kernels are compiled and its
  // pyramid built now, so that the edit only updates the pyramid.
  const bool may_refresh = keep && sweep && k.refresh_budget > 0 && mOptions.subsample == 1;
  if (may_refresh && k.pyramid) t.pyramid_ms = k.sync_pyramid(field, mOptions.march, t.uploaded_bytes);
  if (!reuse && !mOptions.exact && !sweep) {
    const horizon::MarchSchedule steps = horizon::march_schedule(field, mOptions.march);
    steps_count = static_cast<int>(steps.distances.size());
    if (steps_count > kMaxMarchSteps)
      throw std::runtime_error("GPU pipeline: the march has " + std::to_string(steps_count) + " steps, over the kernel's " +
                               std::to_string(kMaxMarchSteps));
    first_distance = steps.distances.front();
    if (k.pyramid) {  // made again only when the field changed (not for a refinement's frames)
      t.pyramid_ms = k.sync_pyramid(field, mOptions.march, t.uploaded_bytes);
      z_bound = static_cast<float>(horizon::march_exit_height_bound(k.pyramid->max_coeff()));
    } else {  // bilinear level-0 heights
      z_bound = static_cast<float>(horizon::march_exit_height_bound(field.heights));
    }
    // The step table (horizon_march.comp's uniform block, padded to MAX_STEPS): per
    // step its distance and its level's geometry, so the kernel reads no level table.
    std::vector<float> table(static_cast<std::size_t>(kMaxMarchSteps) * 8, 0.0f);
    for (int st = 0; st < steps_count; ++st) {
      float* geom = &table[4 * static_cast<std::size_t>(st)];
      float* level = &table[4 * static_cast<std::size_t>(kMaxMarchSteps + st)];
      const int l = steps.levels[st];
      geom[0] = static_cast<float>(steps.distances[st]);
      if (k.pyramid) {
        const terrain::LevelShape& shape = k.pyramid->shape(l);
        geom[1] = static_cast<float>(shape.step_x);
        geom[2] = static_cast<float>(shape.step_y);
        const std::int32_t ints[4] = {shape.width, shape.height, static_cast<std::int32_t>(k.pyramid->offset(l)), l};
        for (int c = 0; c < 4; ++c) level[c] = std::bit_cast<float>(ints[c]);
      }
    }
    t.uploaded_bytes += k.schedule.assign(table);
  }

  // Per-chunk buffers, and every buffer bound.
  // Rows per chunk: march dispatches of ≤ mInvocationsPerDispatch invocations, and σ
  // and output buffers of that size, however large the field.
  int chunk = static_cast<int>(
      std::clamp<std::size_t>(mInvocationsPerDispatch / (static_cast<std::size_t>(w) * bands), 1, h));
  // Sub-sampling: a chunk of full rows needs the coarse rows bracketing it (pass 0 of
  // horizon_march.comp marches them). Chunks of a multiple of s rows start on coarse
  // rows, so neighbouring chunks share one coarse row.
  const int s = mOptions.subsample;
  const horizon::SubsampleAxis coarse_x{w, s}, coarse_y{h, s};
  if (s > 1 && chunk < h && chunk > s) chunk -= chunk % s;
  auto coarse_span = [&](int r0, int rows) {
    return std::pair{coarse_y.bracket(r0).c0, coarse_y.bracket(r0 + rows - 1).c1};
  };
  int coarse_chunk_rows = 0;
  if (s > 1)
    for (int r0 = 0; r0 < h; r0 += chunk) {
      const auto [c0, c1] = coarse_span(r0, std::min(chunk, h - r0));
      coarse_chunk_rows = std::max(coarse_chunk_rows, c1 - c0 + 1);
    }
  const std::size_t coarse_bytes = static_cast<std::size_t>(coarse_chunk_rows) * coarse_x.count() * bands * sizeof(float);
  // The march's horizons of a chunk (the sweep's are computed in the product kernel).
  const std::size_t sigma_bytes = sweep || reuse ? sizeof(float) : static_cast<std::size_t>(chunk) * w * bands * sizeof(float);
  check_storage_size(sigma_bytes, "GPU pipeline: one row of horizon bands");
  Buffer sigma(sigma_bytes);
  Buffer coarse_sigma;
  BufferTexture coarse_tex;  // the sweep's product kernel reads the coarse horizons through it
  if (s > 1) {
    check_storage_size(coarse_bytes, "GPU pipeline: the coarse horizons of a row chunk");
    coarse_sigma = Buffer(coarse_bytes);
    coarse_sigma.bind_storage(kCoarseSigma);
    if (sweep) {
      coarse_tex = BufferTexture(coarse_sigma);
      coarse_tex.bind_sampler(kCoarseSigma);
    }
  }
  Buffer output(static_cast<std::size_t>(chunk) * w * out_bands * sizeof(float));
  k.field.heights().bind_storage(kHeights);  // after the pyramid build, which binds its own
  k.field.row_dx().bind_storage(kRowDx);
  k.headings.bind_storage(kHeadings);
  sigma.bind_storage(kSigma);  // the march writes it; the surface kernel reads this view:
  const BufferTexture sigma_tex(sigma);
  sigma_tex.bind_sampler(kSigma);
  k.field.valid().bind_storage(kValid);
  output.bind_storage(kOutput);
  // The multi-resolution march reads heights, row spacings and coefficients through
  // buffer textures (views of the resident buffers, texture units = their bindings).
  BufferTexture heights_tex, row_dx_tex, coeffs_tex;
  if (!mOptions.exact) {
    if (!sweep) k.schedule.buffer().bind_uniform(kSchedule);
    heights_tex = BufferTexture(k.field.heights());
    row_dx_tex = BufferTexture(k.field.row_dx());
    heights_tex.bind_sampler(kHeights);
    row_dx_tex.bind_sampler(kRowDx);
    if (!sweep) {
      coeffs_tex = BufferTexture(k.pyramid ? k.pyramid->coeffs() : k.no_coeffs);
      coeffs_tex.bind_sampler(kCoeffs);
    }
  }
  if (sh_visibility(mProduct, k.blockers.has_value())) {
    k.table.bind_storage(kTable);  // the sky SH of the SH modes
    if (k.table_tex.id()) k.table_tex.bind_sampler(kTable);
    k.gamma_tex.bind_sampler(kGammaUnit);
  }
  // Stage 0: the sun's shadow, read by the product kernel (lit products with a sun).
  // A partial frame starts from the last frame's shadow of the terrain alone.
  std::vector<terrain::PixelRect> last_rects;  // the last frame's spheres' reach
  if (k.blockers && partial) {
    last_rects = k.blockers->sun_rects();
    last_rects.insert(last_rects.end(), k.blockers->sky_rects().begin(), k.blockers->sky_rects().end());
  }
  if (k.blockers) t.uploaded_bytes += k.blockers->upload(field, k.spheres, mOptions);
  Buffer shadow;
  if (k.sun[Impl::kSunMarch] && partial && k.blockers) {
    shadow = k.terrain_shadow.copy();
    shadow.bind_storage(kShadow);
    t.sun_ms = k.blocker_sun_stage(field);
  } else if (k.sun[Impl::kSunMarch] && !partial) {
    t.sun_ms = k.sun_stage(field, mOptions, mInvocationsPerDispatch, shadow, t);
    if (k.blockers && on_gpu && k.partial_frames) {  // for the partial frames after this one
      k.terrain_shadow.assign(shadow);
    } else {
      k.terrain_shadow = Buffer();
    }
    t.sun_ms += k.blocker_sun_stage(field);
    heights_tex.bind_sampler(kHeights);  // sun_stage bound its own views there
    row_dx_tex.bind_sampler(kRowDx);
  }

  // Stage 2: the march per chunk, or the sweep over the whole field (the product kernel
  // adds each texel's near steps). Stage 3: the product. Row chunks bound a dispatch's
  // length.
  const bool one_dx = !mOptions.exact && horizon::one_row_spacing(field);
  const Impl::VisCache cache = reuse ? read_cache : keep ? Impl::kKeepVis : Impl::kNoCache;
  // A blocked frame shades the whole field without the spheres and then, again with
  // them, the texels their sky bins reach (llvmpipe runs both sides of a branch: one
  // kernel would pay the spheres' code everywhere). A frame that keeps the visibility
  // runs the blocked kernel everywhere (it keeps the floored horizons the spheres' cull
  // reads later), and so does a sub-sampled one (its march runs on whole coarse rows).
  // A one-off frame (no cache) measured no gain: its horizons' march dominates.
  const bool sphere_pass = k.blockers && cache != Impl::kKeepVis && cache != Impl::kNoCache && s == 1;
  const ComputeProgram& products = k.products_kernel(mOptions, sweep, one_dx, cache, !sphere_pass);
  if (keep) k.products_kernel(mOptions, false, one_dx, Impl::kReadVis);  // compiled now: later frames only read
  if (may_refresh) k.products_kernel(mOptions, false, one_dx, Impl::kKeepVis);
  if (reuse || keep) {
    k.vis.bind_storage(kVis);
    if (k.blockers) k.kept_horizons.bind_storage(kKeptHorizons);
  }
  // Without a cache the spheres' horizon cull reads the row chunk's floored slopes.
  Buffer chunk_horizons;
  if (k.blockers && cache == Impl::kNoCache && sh_visibility(mProduct, true)) {
    const std::size_t bytes = static_cast<std::size_t>(chunk) * w * bands * sizeof(float);
    check_storage_size(bytes, "GPU pipeline: the floored horizons of a row chunk");
    chunk_horizons = Buffer(bytes);
    chunk_horizons.bind_storage(kKeptHorizons);
  }
  if (read_cache != Impl::kReadVis) k.kept_sky.bind_storage(kKeptSky);
  if (k.blockers) k.blockers->bind(products);
  if (sweep) {
    const TextureArray& far = SweepTextures::array(k.sweep_textures.far, k.sweep_textures.far_size, w, h, bands);
    const auto sweep_start = Clock::now();
    GpuTimer sweep_timer;
    {
      ScopedGpuTimer timing(sweep_timer);
      // Sub-sampled: the coarse texels alone, those the region's texels mix.
      horizon::MarchOptions o = mOptions.march;
      o.region = horizon::subsample_region(field, o.region, s);
      sweep_pass(k.sweep_kernel(mOptions, false), field, o, k.band_headings, far, k.sweep_textures,
                 -std::numeric_limits<double>::infinity(), s);
    }
    t.march_ms += sweep_timer.elapsed_ms();
    glFinish();  // wall clock too: llvmpipe's timer queries report ~0 for compute
    t.sweep_ms = ms_since(sweep_start);
    far.bind_sampler(kFar);
  }
  if ((may_refresh || (!reuse && !sweep)) && one_dx && !k.march_one_dx) {
    GlslDefines d = k.march_defines;
    d.set("ONE_DX", 1);
    k.march_one_dx.emplace(ComputeProgram::from_embedded("horizon_march.comp", d));
  }
  // A sub-sampled sweep finds its coarse texels' horizons with the march's pass 0; the
  // product kernel mixes them (surface_products.comp).
  const ComputeProgram* march = reuse || (sweep && s == 1) ? nullptr
                                : sweep                     ? &k.swept_march_kernel(mOptions, one_dx)
                                : one_dx                    ? &*k.march_one_dx
                                                            : &*k.march;
  if (march) {
    set_grid_uniforms(*march, field);
    if (one_dx) march->set_uniform("grid_dx", static_cast<float>(field.dx_per_row.front()));
  }
  set_grid_uniforms(products, field);
  if (sweep && products.has_uniform("grid_dx"))  // absent where no product reads horizons
    products.set_uniform("grid_dx", static_cast<float>(field.dx_per_row.front()));
  if (products.has_uniform("first_distance")) products.set_uniform("first_distance", static_cast<float>(first_distance));
  if (products.has_uniform("half_texel_floor")) products.set_uniform("half_texel_floor", sweep ? 1 : 0);

  if (!march) {
  } else if (mOptions.exact) {
    // The CPU stops at t > D·(1 + 1e−12); float t carries ~1e−7 relative error, so the
    // slack is widened to keep the sample at t = D that the CPU keeps.
    const double d_max = mOptions.march.max_distance_m > 0.0 ? mOptions.march.max_distance_m
                                                             : horizon::dem_extent(field);
    march->set_uniform("max_distance", static_cast<float>(d_max * (1.0 + 1e-6)));
  } else if (!sweep) {
    march->set_uniform("steps", steps_count);
    march->set_uniform("z_bound", z_bound);
  }
  if (s > 1 && march) {
    march->set_uniform("coarse_width", coarse_x.count());
    march->set_uniform("coarse_chunk_rows", coarse_chunk_rows);
  }
  if (s > 1 && sweep && products.has_uniform("coarse_width")) {  // absent where no product reads horizons
    products.set_uniform("coarse_width", coarse_x.count());
    products.set_uniform("coarse_chunk_rows", coarse_chunk_rows);
  }

  shading::ProductBands out{w, h, out_bands, {}, {}};
  if (on_gpu) {
    if (k.device_out.size_bytes() != texels * out_bands * sizeof(float)) {
      k.device_out = Buffer();
      k.device_out = Buffer(texels * out_bands * sizeof(float));
    }
  } else {
    out.data.resize(texels * out_bands);
  }
  std::vector<float> chunk_values;
  GpuTimer march_timer, products_timer;
  // Rows r0 … r0 + rows − 1 (≤ chunk), columns c0 … c0 + cols − 1: the march (if any),
  // the product kernel, and the output block into the field's bands.
  auto run_block = [&](const ComputeProgram* march_kernel, const ComputeProgram& product_kernel, int r0, int rows,
                       int c0, int cols) {
    for (const ComputeProgram* p : {march_kernel, &product_kernel}) {
      if (!p) continue;
      p->set_uniform("row_offset", r0);
      p->set_uniform("chunk_rows", chunk);
      p->set_uniform("col_offset", c0);
      p->set_uniform("col_count", cols);
    }
    if (s > 1 && march_kernel) {  // pass 0: the coarse rows bracketing the chunk; pass 1 below
      const auto [y0, y1] = coarse_span(r0, rows);
      march_kernel->set_uniform("coarse_row_offset", y0);
      march_kernel->set_uniform("coarse_rows", y1 - y0 + 1);
      march_kernel->set_uniform("march_pass", 0);
      {
        ScopedGpuTimer timing(march_timer);
        march_kernel->dispatch_covering(coarse_x.count(), y1 - y0 + 1, bands);
      }
      t.march_ms += march_timer.elapsed_ms();
      march_kernel->set_uniform("march_pass", 1);
      if (product_kernel.has_uniform("coarse_row_offset")) product_kernel.set_uniform("coarse_row_offset", y0);
    }
    if (march_kernel && !sweep) {
      {
        ScopedGpuTimer timing(march_timer);
        march_kernel->dispatch_covering(cols, rows, bands);
      }
      t.march_ms += march_timer.elapsed_ms();
    }
    {
      ScopedGpuTimer timing(products_timer);
      product_kernel.dispatch_covering(cols, rows);
    }
    t.products_ms += products_timer.elapsed_ms();
    // Band-major chunk → band-major field, on the GPU or the host: whole rows at once.
    const bool whole_rows = c0 == 0 && cols == w;
    const std::size_t row_bytes = static_cast<std::size_t>(w) * sizeof(float);
    auto chunk_at = [&](int b, int j) { return (static_cast<std::size_t>(b) * chunk + (j - r0)) * w + c0; };
    auto field_at = [&](int b, int j) { return (static_cast<std::size_t>(b) * h + j) * w + c0; };
    if (on_gpu) {
      for (int b = 0; b < out_bands; ++b)
        for (int j = r0; j < r0 + rows; j += whole_rows ? rows : 1)
          glCopyNamedBufferSubData(output.id(), k.device_out.id(), static_cast<GLintptr>(chunk_at(b, j) * sizeof(float)),
                                   static_cast<GLintptr>(field_at(b, j) * sizeof(float)),
                                   static_cast<GLsizeiptr>(whole_rows ? rows * row_bytes : cols * sizeof(float)));
    } else {
      chunk_values.resize(static_cast<std::size_t>(chunk) * w * out_bands);
      output.download(chunk_values.data(), chunk_values.size() * sizeof(float));
      for (int b = 0; b < out_bands; ++b)
        for (int j = r0; j < r0 + rows; ++j)
          std::copy_n(chunk_values.begin() + static_cast<std::ptrdiff_t>(chunk_at(b, j)), cols,
                      out.data.begin() + static_cast<std::ptrdiff_t>(field_at(b, j)));
    }
  };
  // A products kernel's uniforms and spheres set, for a pass of its own over some texels.
  auto prepared = [&](const ComputeProgram& p) -> const ComputeProgram& {
    set_grid_uniforms(p, field);
    if (p.has_uniform("grid_dx")) p.set_uniform("grid_dx", static_cast<float>(field.dx_per_row.front()));
    if (p.has_uniform("first_distance")) p.set_uniform("first_distance", static_cast<float>(first_distance));
    if (p.has_uniform("half_texel_floor")) p.set_uniform("half_texel_floor", sweep ? 1 : 0);
    if (k.blockers) k.blockers->bind(p);
    return p;
  };
  // The one that reads the kept visibility.
  auto kept_reader = [&]() -> const ComputeProgram& {
    return prepared(k.products_kernel(mOptions, false, one_dx, Impl::kReadVis));
  };
  // Incremental: every texel from the kept visibility, then the refreshed ones recomputed.
  const ComputeProgram* reader = incremental ? &kept_reader() : nullptr;
  std::size_t refreshed = 0;
  for (const terrain::PixelRect& r : refresh_rects) refreshed += static_cast<std::size_t>(r.width) * r.height;
  const std::size_t work = incremental ? texels + refreshed : texels;  // the reader's pass, then the rectangles
  std::size_t done = 0;
  if (partial) {  // the texels the last frame's spheres reached and this one's sun reaches, without spheres
    k.changed.emplace(last_rects);
    if (k.blockers) {
      for (const terrain::PixelRect& r : k.blockers->sun_rects()) k.changed->push_back(r);
      for (const terrain::PixelRect& r : *k.changed)
        for (int r0 = r.y0; r0 < r.y1(); r0 += chunk) run_block(nullptr, products, r0, std::min(chunk, r.y1() - r0), r.x0, r.width);
      for (const terrain::PixelRect& r : k.blockers->sky_rects()) k.changed->push_back(r);  // the sphere pass's, below
    }
  }
  for (int r0 = 0; r0 < (partial ? 0 : h); r0 += chunk) {
    const int rows = std::min(chunk, h - r0);
    if (reader) run_block(nullptr, *reader, r0, rows, 0, w);
    else run_block(march, products, r0, rows, 0, w);
    done += static_cast<std::size_t>(rows) * w;
    if (progress) progress(0.99 * static_cast<double>(done) / static_cast<double>(work));
  }
  // The texels the spheres' sky reaches, shaded again with them (the kept sky's frame
  // reads the kept visibility there).
  if (sphere_pass && !incremental) {
    const bool read_vis = cache == Impl::kReadSky || cache == Impl::kReadVis;
    const ComputeProgram& spheres =
        read_vis ? kept_reader() : prepared(k.products_kernel(mOptions, sweep, one_dx, cache, true));
    for (const terrain::PixelRect& r : k.blockers->sky_rects())
      for (int r0 = r.y0; r0 < r.y1(); r0 += chunk)
        run_block(read_vis ? nullptr : march, spheres, r0, std::min(chunk, r.y1() - r0), r.x0, r.width);
  }
  for (const terrain::PixelRect& r : refresh_rects)
    for (int r0 = r.y0; r0 < r.y1(); r0 += chunk) {
      const int rows = std::min(chunk, r.y1() - r0);
      run_block(march, products, r0, rows, r.x0, r.width);
      done += static_cast<std::size_t>(rows) * r.width;
      if (progress) progress(0.99 * static_cast<double>(done) / static_cast<double>(work));
    }
  t.refreshed_texels = incremental ? refreshed : reuse ? 0 : texels;

  // Stage 4: the output transfer.
  throw_on_gl_error("GpuProductPipeline::compute");
  out.band_names = shading::band_names(mProduct, mOptions);
  const bool lit = shading::uses_lighting(mProduct, mOptions);
  const bool eight_bit = shading::traits(mProduct).eight_bit;
  if (on_gpu) {  // linear values: display_scale() says how to tone-map them
  } else if (eight_bit && lit) {
    // The tone map of lighting.h, on the host with the reference's own function.
    for (float& v : out.data)
      if (!std::isnan(v)) v = shading::display_code_value(static_cast<double>(v) * k.display_per_irradiance, mOptions.shaded.tone);
  } else if (eight_bit) {
    for (float& v : out.data)
      if (!std::isnan(v)) v = shading::display_code_value(mOptions.shaded.albedo * v * mOptions.shaded.exposure, mOptions.shaded.tone);
  }
  if (read_cache == Impl::kKeepSky) {
    k.sky_valid = true;
    k.sky_field_id = field.id.value();
    k.sky_revision = field.revision;
    k.sky_model = mOptions.lighting->sky;
  }
  if (keep) {
    k.vis_valid = true;
    k.vis_field_id = field.id.value();
    k.vis_revision = field.revision;
    if (!incremental) k.refresh.reset(w, h);
  }
  t.stale_texels = keep || reuse ? k.refresh.stale_texels() : 0;
  if (on_gpu) k.last_frame = {true, field.id.value(), field.revision, k.lighting_serial};
  if (vis_product) ++k.frames;
  if (progress) progress(1.0);
  t.compile_ms = k.compile_ms;
  t.frame_ms = ms_since(start);
  if (timings) *timings = t;
  return out;
}

}  // namespace skylit::gpu
