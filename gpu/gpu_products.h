// Host driver for the exact-horizon products on the GPU: uploads a HeightField, runs
// shaders/horizon_exact.comp (per texel and azimuth) and shaders/horizon_products.comp
// (per texel), and reads back the `horizon` and `svf` products (DESIGN.md "Products"),
// laid out like the CPU reference's shading::compute_product with `exact` set.
//
// Semantics are those of shading::exact_max_elevation (horizon_exact.h), edge rules
// included (shading/horizon_ray.h); the two agree to float32 rounding.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "shading/horizon_exact.h"
#include "shading/products.h"
#include "terrain/height_field.h"

namespace skylit::gpu {

struct GpuHorizonOptions {
  int azimuths = 32;            // W: band k at geographic azimuth k·360°/W
  shading::ExactMarch march;    // step (texels), max distance (0 = DEM extent), curvature
};

// Helpers shared with gpu_pipeline.cpp.
// Band name of the CPU reference's horizon product ("horizon_az045.0").
std::string horizon_band_name(int k, int azimuths);
// Throws std::runtime_error("<what> needs … bytes, over GL_MAX_SHADER_STORAGE_BLOCK_SIZE …")
// (needs a current context).
void check_storage_size(std::size_t bytes, const char* what);
// field.valid packed 1 byte per texel, four per word, little end first (the shaders'
// `valid_bytes`).
std::vector<std::uint32_t> pack_valid_bytes(const terrain::HeightField& field);
// Horizontal direction (east, north) of band k of W (shading/azimuth.h; cardinal
// components are exact zeros, so rays along the grid's edges stay on it).
shading::Heading band_heading(int k, int azimuths);

// The options compute_product(field, product, options) uses for its exact march:
// W = march.azimuths for `horizon`, exact_options.sky_azimuths for `svf`.
GpuHorizonOptions exact_options_for(shading::Product product, const shading::ProductOptions& options);

struct GpuHorizonProducts {
  shading::ProductBands horizon;  // W bands, degrees, floored at the receiver's ground
  shading::ProductBands svf;      // 1 band
  // GPU time of the two kernels (GL_TIME_ELAPSED; Mesa llvmpipe reports ~0 for
  // compute work, so on llvmpipe only wall_ms means anything).
  double march_ms = 0.0;
  double products_ms = 0.0;
  double wall_ms = 0.0;           // whole compute(): uploads, kernels, read-back
};

// Compiles the kernels once for a set of options (W, step and curvature are compiled
// in as generated #defines); compute() may then run on any number of fields. Needs a
// current GL 4.5 context (gpu/gl_context.h) for its whole life.
class GpuExactHorizon {
 public:
  // Throws std::invalid_argument for W < 1, step ≤ 0 or a negative max distance, and
  // std::runtime_error if a kernel fails to compile.
  explicit GpuExactHorizon(const GpuHorizonOptions& options);
  ~GpuExactHorizon();
  GpuExactHorizon(const GpuExactHorizon&) = delete;
  GpuExactHorizon& operator=(const GpuExactHorizon&) = delete;

  const GpuHorizonOptions& options() const { return mOptions; }

  // Nodata texels are NaN in both products. Throws std::runtime_error if the field
  // exceeds the GPU's storage-buffer limits (split it into tiles with a halo).
  GpuHorizonProducts compute(const terrain::HeightField& field) const;

 private:
  struct Kernels;
  GpuHorizonOptions mOptions;
  std::unique_ptr<Kernels> mKernels;
};

}  // namespace skylit::gpu
