// The products of `skylit shade` on the GPU (DESIGN.md pipeline steps 2–4, 7–9):
// horizon, svf, skyview, shaded (uniform sky, or lit by ProductOptions::lighting),
// shadow and irradiance, laid out and named like the CPU reference's
// shading::compute_product with the same ProductOptions, which it matches to float32
// rounding (tests/gpu_products_test.cpp).
//
// Stages (gpu/README.md "Product pipeline"):
//  0. lit products with a sun, and shadow: shaders/sun_shadow.comp, the sun's own march
//     (shading::sun_march_options() schedule from C++, level-0 bilinear heights) and
//     the disc fraction above the horizon and tangent-plane lines (shading/sky/sun_disc);
//  1. height pyramid: built on the GPU (gpu/gpu_pyramid.h, terrain::HeightPyramid's
//     levels to float32 rounding) from the resident heights; the step schedule from
//     horizon::march_schedule;
//  2. shaders/horizon_march.comp: multi-resolution march per texel and azimuth with
//     the CPU marcher's own step schedule (t_s, level l_s) → raw horizons;
//     with options.exact, shaders/horizon_exact.comp (the dense exact march) instead;
//     where shading::uses_sweep, stages 1–2 are the sweep instead: horizon_sweep.comp
//     over the whole field (far-slope codes, W layers of 16 bits), and stage 3 adds
//     each texel's near steps itself (no raw-horizon buffer);
//  3. shaders/surface_products.comp: per texel, Horn normal and the product
//     (horizon floors, svf, exact skyview slice integrals, or NLP slices → linear
//     or B-spline wedge assembly → sky×BRDF table shading);
//     irradiance and lit shaded: π·V·T(n) per channel from the lighting's sky tables
//     plus the sun DNI·max(n·s, 0)·shadow;
//  4. host: read-back; shaded gets albedo, exposure (lit: lighting.h's tone map) and
//     shading::srgb_code_value.
// A blocked pipeline (sphere blockers, gpu/gpu_blockers.h) adds blocker_sun.comp after
// stage 0 and the spheres' sky change to stage 3 (surface_products.comp BLOCKERS).
//
// Edge rules (exact-zero cardinal headings, samples within edge_epsilon_texels of the
// last row/column count) are the CPU reference's, from shading/horizon/horizon_ray.h.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "gpu/buffers.h"
#include "shading/horizon/halo.h"
#include "shading/products.h"
#include "shading/renderer.h"
#include "terrain/height_field.h"

namespace skylit::gpu {

// Whether the pipeline computes `product` with `options`: every product; the lit ones
// (shading::uses_lighting: shadow, irradiance, shaded with a lighting) need
// ProductOptions::lighting and the multi-resolution march (not options.exact, whose
// sun uses the exact march on the CPU); shaded and irradiance need the sky × BRDF table
// shading mode (ShadedOptions::mode, the default).
bool gpu_supports(shading::Product product, const shading::ProductOptions& options);

// Where compute()'s time went (shading/renderer.h says which clock each field uses).
using GpuPipelineTimings = shading::FrameTimings;

// Whether two option sets bake the same lighting into a pipeline's kernels (lit or not,
// the sun on or off, colour, a sky or none): set_lighting() takes only such a change.
bool same_baked_lighting(shading::Product product, const shading::ProductOptions& a, const shading::ProductOptions& b);

// Compiles the kernels for one product and set of options; compute() may then run on
// any number of fields. Needs a current GL 4.5 context (gpu/gl_context.h) for its whole
// life. The shading table (uniform sky of radiance 1 above the horizontal, Lambert,
// the reference's default shading mode) is built once here.
class GpuProductPipeline {
 public:
  // Throws std::invalid_argument for options compute_product rejects or
  // !gpu_supports(product, options), and std::runtime_error if a kernel fails to compile.
  // `blocked`: shade sphere blockers (set_spheres) in the products whose traits say so
  // (their kernels bake them in; gpu/gpu_blockers.h): std::invalid_argument where
  // gpu_lacks_blockers says why not.
  GpuProductPipeline(shading::Product product, const shading::ProductOptions& options, bool blocked = false);
  ~GpuProductPipeline();
  GpuProductPipeline(const GpuProductPipeline&) = delete;
  GpuProductPipeline& operator=(const GpuProductPipeline&) = delete;

  shading::Product product() const { return mProduct; }
  // Bound on march invocations (texels × azimuths) per dispatch: fields are processed in
  // row chunks of that size, which bounds a dispatch's run time (progress, watchdogs)
  // and the σ and output buffers (16 MiB each at the default), however large the field.
  void set_invocations_per_dispatch(std::size_t n) { mInvocationsPerDispatch = n; }
  const shading::ProductOptions& options() const { return mOptions; }

  // Per-frame inputs: the sun and sky (uniforms and the sky tables; the lighting must
  // match the constructor's in what same_baked_lighting compares, else std::logic_error),
  // and the tone map of `shaded`.
  void set_lighting(const shading::Lighting& lighting);
  // `shaded`'s exposure and tone curve (neither baked in: the codes and the tone map's
  // display scale are made on the host).
  void set_tone_map(double exposure, shading::ToneCurve tone);
  // The texels whose horizons are wanted (MarchOptions::region; not baked in).
  void set_region(const terrain::PixelRect& region);
  // `shaded` and `irradiance`: keep the visibility (SH_COEFFS floats per texel) of a
  // compute() for the next ones on the same field revision, which then skip the
  // horizons and the visibility. Off: the second compute() starts keeping. A field too
  // large for one storage buffer keeps nothing.
  void keep_visibility(bool keep);
  // A blocked pipeline's spheres for the next compute()s (field frame: FrameInputs).
  // Blocked frames keep no visibility: the spheres' horizon cull reads the horizons.
  void set_spheres(std::span<const blockers::Sphere> spheres);
  // Forgets the kept visibility and the sun's kept far slopes.
  void drop_visibility();
  // Incremental refresh of the kept visibility after an edit (gpu/visibility_refresh.h).
  // With a budget > 0, the compute() after one edit of a kept field (revision one past the
  // kept one, its last_dirty inside the grid) recomputes only the edited rectangle grown
  // by kRefreshMarginTexels, and each later compute() on that revision about `budget`
  // more texels, nearest the edit first, until every texel is again what a whole march
  // gives; texels not reached yet keep the visibility of the field before the edit. The
  // refreshed texels are marched also where the options sweep, since the sweep is not
  // local: a swept field converges to the march's horizons, which differ from the
  // sweep's by the two methods' errors (docs/accuracy.md). 0 (the default): the edit's
  // compute() recomputes the whole field as the options say. Sub-sampled horizons
  // (subsample > 1) always recompute the whole field.
  void set_refresh_budget(std::size_t texels_per_frame);
  // Where the sun's horizon is swept (shading::sun_sweeps), keep each texel's horizon
  // elevation along the sun's heading (far slopes and near steps, 4 B a texel) for later
  // compute()s on the same field revision while the heading stays within `radians` of
  // the one it was swept along (and the sun no more than half of shading::kSunFloorMargin
  // lower: the sweep's floor); the disc's pass still runs for the frame's own sun. A
  // slope from k texels away then belongs to a ray up to k·radians texels off the sun's
  // (docs/accuracy.md measures what that costs).
  // 0, the default: every compute() sweeps, as the reference does.
  void set_sun_heading_tolerance(double radians);
  static constexpr double kMaxSunHeadingTolerance = 0.1;  // rad (5.7°)
  // Lit products on a kept visibility: keep each texel's sky irradiance π·V·T(n) without
  // spheres, and read it in later compute()s on the same field revision under the same
  // sky model (the same Lighting::sky object, whose tables set_lighting then keeps too);
  // texels a sphere's sky bin reaches are shaded whole, and the sun term is every
  // frame's own, so the frames equal those without keeping bit for bit. Off by default.
  void keep_sky_irradiance(bool keep);
  // Where the far slopes are swept (the sky's headings and the sun's): on the host's cores
  // (horizon::sweep_far_slopes, in double, its codes uploaded) or by horizon_sweep.comp.
  // The default is the host on a software rasterizer (llvmpipe runs the GLSL sweep on
  // the same cores, ~3.5× slower), the kernel on a GPU. Either gives the same codes up to
  // one code where float and double round a slope differently.
  void set_sweeps_on_host(bool on_host);
  bool sweeps_on_host() const;  // needs the pipeline's context current
  // compute_on_gpu() after compute_on_gpu() on the same field revision, under the same
  // lighting (set_lighting unchanged) and with the sky irradiance kept: the spheres alone
  // may have moved, so only the texels their bins reach, the last frame's or this one's,
  // are shaded again (the sun's shadow there from the last frame's terrain shadow); the
  // rest of the bands stay. The bands equal a whole frame's bit for bit. On by default.
  void set_partial_frames(bool partial);
  // The texels the last compute_on_gpu() wrote, when it was such a partial frame (empty:
  // none); nothing when it wrote every texel.
  const std::optional<std::vector<terrain::PixelRect>>& last_changed() const;
  // The texels next to an edit whose normals and kernels read it.
  static constexpr int kRefreshMarginTexels = horizon::kKernelMarginTexels;

  // The field stays resident on the GPU until the next call: the same HeightField
  // object after one edit (terrain/editing.h) re-uploads only the edited rows
  // (gpu/resident_field.h says how the field is recognised); any other is uploaded whole.
  // Nodata texels are NaN. Throws std::runtime_error if the field exceeds the GPU's
  // storage-buffer limits (split it into tiles with a halo). `progress` is called with
  // the fraction of rows done, from the calling thread.
  shading::ProductBands compute(const terrain::HeightField& field, const shading::ProgressCallback& progress = {},
                                GpuPipelineTimings* timings = nullptr) const;

  // compute(), with the bands left on the GPU: band-major float32 [(b·height + j)·width + i],
  // NaN on nodata, valid until the next call. `shaded` holds linear values there, before
  // the host's tone map: srgb_code_value(v · display_scale()) gives compute()'s codes.
  const Buffer& compute_on_gpu(const terrain::HeightField& field, const shading::ProgressCallback& progress = {},
                               GpuPipelineTimings* timings = nullptr) const;
  double display_scale() const;

  // Diagnostics: the sweep's far-slope codes (horizon::sweep_far_slopes' layout, one
  // field-sized layer per band, band-major) as the last compute() left them; empty if it
  // did not sweep. Tests compare them with the reference's codes.
  std::vector<std::uint16_t> far_codes() const;

 private:
  shading::ProductBands run(const terrain::HeightField& field, const shading::ProgressCallback& progress,
                            GpuPipelineTimings* timings, bool on_gpu) const;
  struct Impl;
  shading::Product mProduct;
  shading::ProductOptions mOptions;
  std::unique_ptr<Impl> mImpl;
  std::size_t mInvocationsPerDispatch = std::size_t{1} << 22;
};

}  // namespace skylit::gpu
