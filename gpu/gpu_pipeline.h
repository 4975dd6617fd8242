// The products of `skylit shade` on the GPU (DESIGN.md pipeline steps 2–4, 7–9):
// horizon, svf, skyview, shaded (uniform sky, or lit by ProductOptions::lighting),
// shadow and irradiance, laid out and named like the CPU reference's
// shading::compute_product with the same ProductOptions, which it matches to float32
// rounding (tests/gpu_products_test.cpp).
//
// Stages (gpu/README.md "Product pipeline"):
//  0. lit products with a sun, and shadow: shaders/sun_shadow.comp, the sun's own march
//     (shading::sun_march_options() schedule from C++, level-0 bilinear heights) and
//     the disc fraction above the horizon and tangent-plane lines (shading/sun_disc);
//  1. height pyramid: built on the GPU (gpu/gpu_pyramid.h, terrain::HeightPyramid's
//     levels to float32 rounding) from the resident heights; the step schedule from
//     shading::march_schedule;
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
//
// Edge rules (exact-zero cardinal headings, samples within edge_epsilon_texels of the
// last row/column count) are the CPU reference's, from shading/horizon_ray.h.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "shading/products.h"
#include "terrain/height_field.h"

namespace skylit::gpu {

// Whether the pipeline computes `product` with `options`: every product; the lit ones
// (shading::uses_lighting: shadow, irradiance, shaded with a lighting) need
// ProductOptions::lighting and the multi-resolution march (not options.exact, whose
// sun uses the exact march on the CPU); shaded and irradiance need the sky × BRDF table
// shading mode (ShadedOptions::mode, the default).
bool gpu_supports(shading::Product product, const shading::ProductOptions& options);

struct GpuPipelineTimings {
  double pyramid_ms = 0.0;   // GPU pyramid build, wall clock to glFinish (0 without one)
  double sun_ms = 0.0;       // GPU timer: the sun shadow pass and its sweep (lit products, shadow)
  double upload_ms = 0.0;    // the height field to the GPU (wall clock)
  // Bytes sent to the GPU by this compute(): heights, valid mask, row spacing (only the
  // edited rows of a resident field, gpu/resident_field.h), and the step schedules and
  // pyramid tables where they changed.
  std::size_t uploaded_bytes = 0;
  double sweep_ms = 0.0;     // the sweep's far field, wall clock to glFinish (0 without it)
  double march_ms = 0.0;     // GPU timer, the sweep included (Mesa llvmpipe reports ~0 for compute)
  double products_ms = 0.0;  // GPU timer
  double wall_ms = 0.0;      // whole compute(), read-back included
};

// Compiles the kernels for one product and set of options; compute() may then run on
// any number of fields. Needs a current GL 4.5 context (gpu/gl_context.h) for its whole
// life. The shading table (uniform sky of radiance 1 above the horizontal, Lambert,
// the reference's default shading mode) is built once here.
class GpuProductPipeline {
 public:
  // Throws std::invalid_argument for options compute_product rejects or
  // !gpu_supports(product, options), and std::runtime_error if a kernel fails to compile.
  GpuProductPipeline(shading::Product product, const shading::ProductOptions& options);
  ~GpuProductPipeline();
  GpuProductPipeline(const GpuProductPipeline&) = delete;
  GpuProductPipeline& operator=(const GpuProductPipeline&) = delete;

  shading::Product product() const { return mProduct; }
  // Bound on march invocations (texels × azimuths) per dispatch: fields are processed in
  // row chunks of that size, which bounds a dispatch's run time (progress, watchdogs)
  // and the σ and output buffers (16 MiB each at the default), however large the field.
  void set_invocations_per_dispatch(std::size_t n) { mInvocationsPerDispatch = n; }
  const shading::ProductOptions& options() const { return mOptions; }

  // The field stays resident on the GPU until the next call: the same HeightField
  // object after one edit (terrain/editing.h) re-uploads only the edited rows
  // (gpu/resident_field.h says how the field is recognised); any other is uploaded whole.
  // Nodata texels are NaN. Throws std::runtime_error if the field exceeds the GPU's
  // storage-buffer limits (split it into tiles with a halo). `progress` is called with
  // the fraction of rows done, from the calling thread.
  shading::ProductBands compute(const terrain::HeightField& field, const shading::ProgressCallback& progress = {},
                                GpuPipelineTimings* timings = nullptr) const;

  // Diagnostics: the sweep's far-slope codes (shading::sweep_far_slopes' layout, one
  // field-sized layer per band, band-major) as the last compute() left them; empty if it
  // did not sweep. Tests compare them with the reference's codes.
  std::vector<std::uint16_t> far_codes() const;

 private:
  struct Impl;
  shading::Product mProduct;
  shading::ProductOptions mOptions;
  std::unique_ptr<Impl> mImpl;
  std::size_t mInvocationsPerDispatch = std::size_t{1} << 22;
};

}  // namespace skylit::gpu
