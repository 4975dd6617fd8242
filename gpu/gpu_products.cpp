#include "gpu/gpu_products.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "gpu/buffers.h"
#include "gpu/compute_program.h"
#include "gpu/gl_context.h"
#include "gpu/timer.h"
#include "shading/azimuth.h"
#include "shading/horizon_ray.h"

namespace skylit::gpu {
namespace {

// Storage-buffer binding points, handed to the shaders as generated #defines.
enum Binding : int {
  kHeights = 0,
  kRowDx = 1,
  kHeadings = 2,
  kSigma = 3,
  kValid = 4,
  kHorizonDeg = 5,
  kSvf = 6,
};

constexpr int kLocalSize = 8;  // 8×8 texels per work group

GlslDefines horizon_defines(const GpuHorizonOptions& o) {
  GlslDefines d;
  d.set("LOCAL_SIZE_X", kLocalSize)
      .set("LOCAL_SIZE_Y", kLocalSize)
      .set("AZIMUTHS", o.azimuths)
      .set("STEP_TEXELS", o.march.step_texels)
      .set("INV_TWO_R_EFF", o.march.curvature.drop_per_square_metre())
      .set("HEIGHTS_BINDING", kHeights)
      .set("ROW_DX_BINDING", kRowDx)
      .set("HEADINGS_BINDING", kHeadings)
      .set("SIGMA_BINDING", kSigma)
      .set("VALID_BINDING", kValid)
      .set("HORIZON_DEG_BINDING", kHorizonDeg)
      .set("SVF_BINDING", kSvf);
  return d;
}

// horizon_ray.glsl's uniforms; a kernel variant may not use all of them (grid_dy is
// dropped by horizon_products.comp without curvature).
void set_grid_uniforms(const ComputeProgram& p, const terrain::HeightField& f) {
  p.set_uniform("grid_width", f.width);
  p.set_uniform("grid_height", f.height);
  if (p.has_uniform("grid_dy")) p.set_uniform("grid_dy", static_cast<float>(f.dy));
}

}  // namespace

struct GpuExactHorizon::Kernels {
  ComputeProgram march;
  ComputeProgram products;
  Buffer headings;
};

std::string horizon_band_name(int k, int w) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "horizon_az%05.1f", 360.0 * k / w);
  return buf;
}

void check_storage_size(std::size_t bytes, const char* what) {
  GLint64 max_block = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &max_block);
  if (bytes > static_cast<std::size_t>(max_block))
    throw std::runtime_error(std::string(what) + " needs " + std::to_string(bytes) +
                             " bytes, over GL_MAX_SHADER_STORAGE_BLOCK_SIZE " + std::to_string(max_block) +
                             "; split the field into tiles");
}

std::vector<std::uint32_t> pack_valid_bytes(const terrain::HeightField& field) {
  std::vector<std::uint32_t> words((field.size() + 3) / 4, 0);
  for (std::size_t t = 0; t < field.size(); ++t)
    if (field.valid[t]) words[t / 4] |= 1u << (8 * (t % 4));
  return words;
}

shading::Heading band_heading(int k, int azimuths) {
  return shading::heading_from_geographic(shading::band_azimuth(k, azimuths));
}

GpuHorizonOptions exact_options_for(shading::Product product, const shading::ProductOptions& options) {
  GpuHorizonOptions o;
  o.azimuths = product == shading::Product::Horizon ? options.march.azimuths
                                                    : options.exact_options.sky_azimuths;
  o.march = {options.exact_options.step_texels, options.march.max_distance_m,
             options.march.curvature};
  return o;
}

GpuExactHorizon::GpuExactHorizon(const GpuHorizonOptions& options) : mOptions(options) {
  if (options.azimuths < 1) throw std::invalid_argument("GpuExactHorizon: azimuths must be >= 1");
  if (!(options.march.step_texels > 0.0))
    throw std::invalid_argument("GpuExactHorizon: step must be > 0");
  if (!(options.march.max_distance_m >= 0.0))
    throw std::invalid_argument("GpuExactHorizon: max distance must be >= 0");

  // Band headings from the C++ azimuth convention, so GLSL has no azimuth formula.
  std::vector<float> headings;
  for (int k = 0; k < options.azimuths; ++k) {
    const shading::Heading u = band_heading(k, options.azimuths);
    headings.push_back(static_cast<float>(u.east));
    headings.push_back(static_cast<float>(u.north));
  }
  const GlslDefines defines = horizon_defines(options);
  mKernels.reset(new Kernels{ComputeProgram::from_embedded("horizon_exact.comp", defines),
                             ComputeProgram::from_embedded("horizon_products.comp", defines),
                             Buffer::from(std::span<const float>(headings))});
}

GpuExactHorizon::~GpuExactHorizon() = default;

GpuHorizonProducts GpuExactHorizon::compute(const terrain::HeightField& field) const {
  if (field.width < 1 || field.height < 1) throw std::invalid_argument("GpuExactHorizon: empty field");
  const auto start = std::chrono::steady_clock::now();
  const int w = field.width, h = field.height, bands = mOptions.azimuths;
  const std::size_t texels = field.size();
  check_storage_size(texels * sizeof(float) * bands, "GpuExactHorizon: the horizon bands");

  const std::vector<float> row_dx(field.dx_per_row.begin(), field.dx_per_row.end());
  const std::vector<std::uint32_t> valid_words = pack_valid_bytes(field);

  Buffer heights = Buffer::from(std::span<const float>(field.heights));
  Buffer dx = Buffer::from(std::span<const float>(row_dx));
  Buffer valid = Buffer::from(std::span<const std::uint32_t>(valid_words));
  Buffer sigma(texels * bands * sizeof(float));
  Buffer horizon_deg(texels * bands * sizeof(float));
  Buffer svf(texels * sizeof(float));
  heights.bind_storage(kHeights);
  dx.bind_storage(kRowDx);
  mKernels->headings.bind_storage(kHeadings);
  sigma.bind_storage(kSigma);
  valid.bind_storage(kValid);
  horizon_deg.bind_storage(kHorizonDeg);
  svf.bind_storage(kSvf);

  // The CPU stops at t > D·(1 + 1e−12); float t carries ~1e−7 relative error, so the
  // slack is widened to keep the sample at t = D that the CPU keeps.
  const double d_max = mOptions.march.max_distance_m > 0.0 ? mOptions.march.max_distance_m
                                                           : shading::dem_extent(field);
  const ComputeProgram& march = mKernels->march;
  set_grid_uniforms(march, field);
  march.set_uniform("max_distance", static_cast<float>(d_max * (1.0 + 1e-6)));
  march.set_uniform("edge_eps", static_cast<float>(shading::edge_epsilon_texels(field)));
  march.set_uniform("row_offset", 0);  // one dispatch: the sigma buffer holds every row
  march.set_uniform("chunk_rows", h);
  const ComputeProgram& products = mKernels->products;
  set_grid_uniforms(products, field);

  GpuTimer march_timer, products_timer;
  {
    ScopedGpuTimer timing(march_timer);
    march.dispatch_covering(w, h, bands);
  }
  {
    ScopedGpuTimer timing(products_timer);
    products.dispatch_covering(w, h);
  }

  GpuHorizonProducts out;
  out.march_ms = march_timer.elapsed_ms();
  out.products_ms = products_timer.elapsed_ms();

  out.horizon = {w, h, bands, horizon_deg.download_all<float>(), {}};
  for (int k = 0; k < bands; ++k) out.horizon.band_names.push_back(horizon_band_name(k, bands));
  out.svf = {w, h, 1, svf.download_all<float>(),
             {std::string(shading::product_name(shading::Product::Svf))}};
  throw_on_gl_error("GpuExactHorizon::compute");
  out.wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace skylit::gpu
