#include "gpu/gpu_renderer.h"

#include "gpu/field_limits.h"
#include "gpu/gpu_blockers.h"
#include "gpu/timer.h"
#include "shading/local_products.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace skylit::gpu {
namespace {

using shading::Product;

// One line: EGL explains each platform's failure on its own lines.
std::string one_line(std::string text) {
  std::replace_if(text.begin(), text.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
  return text;
}

std::unique_ptr<HeadlessContext> make_context(double& ms) {
  const auto start = std::chrono::steady_clock::now();
  try {
    auto context = std::make_unique<HeadlessContext>();
    ms = ms_since(start);
    return context;
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(one_line(e.what()));
  }
}

// Options that give the same compiled pipeline: the kernels bake in the horizon and
// shading options (not the wanted region: GpuProductPipeline::set_region), the
// lighting's shape and the blockers' merge angle and log* table (gpu_blockers.h); the
// albedo is applied on the host.
bool same_pipeline(Product product, const shading::ProductOptions& a, const shading::ProductOptions& b, bool blocked) {
  return shading::same_baked_horizon_options(a, b) && same_baked_lighting(product, a, b) &&
         a.shaded.albedo == b.shaded.albedo &&
         (!blocked || (a.blockers.merge_sin == b.blockers.merge_sin &&
                       a.blockers.blocker.log_clip == b.blockers.blocker.log_clip));
}

}  // namespace

GpuRenderer::GpuRenderer() : context_(make_context(context_ms_)) {}

GpuRenderer::GpuRenderer(std::unique_ptr<HeadlessContext> context) : context_(std::move(context)) {
  if (!context_) throw std::invalid_argument("GpuRenderer: no context");
}

GpuRenderer::~GpuRenderer() {
  context_->make_current();  // GL objects die while their context is current
  cache_.clear();
}

std::string GpuRenderer::description() const {
  return "gpu (" + context_->renderer() + ", " + context_->platform() + ")";
}

void GpuRenderer::set_options(const shading::ProductOptions& options) {
  if (!shading::same_horizon_options(options, options_)) {
    outputs_.clear();
    frames_ = 0;
  }
  options_ = options;
}

void GpuRenderer::drop_horizons() {
  context_->make_current();
  for (Entry& e : cache_) e.pipeline->drop_visibility();
  outputs_.clear();
  frames_ = 0;
}

std::optional<std::string> GpuRenderer::lacks(Product product, const shading::ProductOptions& options) const {
  if (gpu_supports(product, options)) return std::nullopt;
  const std::string name(shading::product_name(product));
  if (options.exact && shading::uses_lighting(product, options))
    return "the GPU cannot compute '" + name + "' with the exact march (the sun's exact march is CPU-only)";
  return "the GPU cannot compute '" + name + "' with these options";
}

bool GpuRenderer::fits_field(int width, int height, Product product, const shading::ProductOptions& options) {
  if (shading::traits(product).local) return true;  // computed on the host
  context_->make_current();
  return field_fits_gpu(width, height, product, options);
}

std::optional<std::string> GpuRenderer::lacks_blockers(Product product, const shading::ProductOptions& options) const {
  return gpu_lacks_blockers(product, options);
}

GpuProductPipeline& GpuRenderer::pipeline_for(Product product, const shading::ProductOptions& options, bool blocked) {
  const auto it = std::find_if(cache_.begin(), cache_.end(), [&](const Entry& e) {
    return e.product == product && e.blocked == blocked && same_pipeline(product, e.options, options, blocked);
  });
  if (it != cache_.end()) return *it->pipeline;
  if (cache_.size() == kCachedPipelines) cache_.pop_front();  // the oldest setting
  const auto start = std::chrono::steady_clock::now();
  cache_.push_back({product, options, blocked, std::make_unique<GpuProductPipeline>(product, options, blocked)});
  timings_.compile_ms += ms_since(start);
  return *cache_.back().pipeline;
}

bool GpuRenderer::blocked_pipeline(Product product, const shading::ProductOptions& options,
                                   const shading::FrameInputs& inputs) const {
  if (shading::blocked_frame(product, inputs)) return true;
  return blockers_expected_ && shading::traits(product).blocked && !lacks_blockers(product, options);
}

GpuProductPipeline& GpuRenderer::prepare(Product product, const shading::ProductOptions& options,
                                         const shading::FrameInputs& inputs) {
  context_->make_current();
  const bool blocked = blocked_pipeline(product, options, inputs);
  GpuProductPipeline& pipeline = pipeline_for(product, options, blocked);  // its construction compiles
  last_ = &pipeline;
  if (blocked) pipeline.set_spheres(inputs.spheres);
  if (shading::uses_lighting(product, options)) pipeline.set_lighting(*options.lighting);
  pipeline.set_tone_map(options.shaded.exposure, options.shaded.tone);
  pipeline.set_region(options.march.region);
  pipeline.keep_visibility(keep_);
  pipeline.set_refresh_budget(refresh_budget_);
  pipeline.set_sun_heading_tolerance(sun_heading_tolerance_);
  pipeline.keep_sky_irradiance(keep_sky_);
  pipeline.set_partial_frames(partial_frames_);
  return pipeline;
}

void GpuRenderer::finish_frame(std::chrono::steady_clock::time_point start) {
  if (!context_reported_) timings_.context_ms = context_ms_;
  context_reported_ = true;
  ++frames_;
  timings_.frame_ms = ms_since(start);
}

shading::ProductOptions GpuRenderer::begin_frame(Product product, const shading::FrameInputs& inputs) {
  if (!field_) throw std::logic_error("GpuRenderer: no field (set_field)");
  shading::validate(inputs);
  shading::ProductOptions options = shading::frame_options(options_, inputs);
  if (const auto why = lacks(product, options)) throw std::invalid_argument(*why);
  if (shading::blocked_frame(product, inputs))
    if (const auto why = lacks_blockers(product, options)) throw std::invalid_argument(*why);
  timings_ = {};
  return options;
}

shading::ProductBands GpuRenderer::frame(Product product, const shading::FrameInputs& inputs,
                                         const shading::ProgressCallback& progress) {
  const shading::ProductOptions options = begin_frame(product, inputs);
  const auto start = std::chrono::steady_clock::now();
  if (shading::traits(product).local) {  // host work: no kernel to prepare
    shading::ProductBands out = shading::compute_local_product(*field_, product, options);
    finish_frame(start);
    return out;
  }
  const auto render = [&] {
    GpuProductPipeline& pipeline = prepare(product, options, inputs);
    const double construction_ms = timings_.compile_ms;
    shading::ProductBands bands = pipeline.compute(*field_, progress, &timings_);
    timings_.compile_ms += construction_ms;
    return bands;
  };
  shading::ProductBands out = shading::FrameIndependentCache::applies(product) && !shading::blocked_frame(product, inputs)
                                  ? outputs_.get(product, *field_, options, keep_ || frames_ > 0, progress,
                                                 timings_.horizons_reused, render)
                                  : render();
  finish_frame(start);
  return out;
}

GpuFrame GpuRenderer::frame_on_gpu(Product product, const shading::FrameInputs& inputs,
                                   const shading::ProgressCallback& progress) {
  if (shading::traits(product).local)
    throw std::invalid_argument(std::string(shading::product_name(product)) +
                                " is computed on the host (a local product): it has no GPU buffer");
  const shading::ProductOptions options = begin_frame(product, inputs);
  const auto start = std::chrono::steady_clock::now();
  const GpuProductPipeline* previous = last_on_gpu_;
  GpuProductPipeline& pipeline = prepare(product, options, inputs);
  const double construction_ms = timings_.compile_ms;
  const Buffer& bands = pipeline.compute_on_gpu(*field_, progress, &timings_);
  timings_.compile_ms += construction_ms;
  finish_frame(start);
  last_on_gpu_ = &pipeline;
  const int band_count = static_cast<int>(bands.size_bytes() / (field_->size() * sizeof(float)));
  GpuFrame out{bands, field_->width, field_->height, band_count, pipeline.display_scale(), std::nullopt, ++on_gpu_frames_};
  if (previous == &pipeline) out.changed = pipeline.last_changed();  // else another buffer was the last frame's
  return out;
}

}  // namespace skylit::gpu
