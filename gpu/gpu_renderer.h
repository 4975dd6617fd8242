// The GPU renderer (shading/renderer.h): one headless OpenGL 4.5 context, the height
// field resident on it, and compiled pipelines (gpu/gpu_pipeline.h) cached by what their
// kernels bake in: the product, the horizon and shading options, and the lighting's
// shape (lit, sun on, colour, a sky). A frame sets the sun, sky and exposure as uniforms
// and tables; `shaded` and `irradiance` keep their visibility on the GPU between frames
// (GpuProductPipeline::keep_visibility), horizon, svf and skyview their bands.
#pragma once

#include "gpu/gl_context.h"
#include "gpu/gpu_pipeline.h"
#include "shading/renderer.h"

#include <chrono>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <vector>

namespace skylit::gpu {

// A frame left on the GPU (the viewer draws it without a copy): band-major float32
// [(b·height + j)·width + i], NaN on nodata; `shaded` in linear values, shown as
// shading::srgb_code_value(v · display_scale). Valid until the renderer's next frame.
struct GpuFrame {
  const Buffer& bands;
  int width = 0, height = 0, band_count = 0;
  double display_scale = 1.0;
  // The texels that differ from the renderer's previous frame_on_gpu() (serial − 1),
  // when that was of the same product and this one shaded only what its spheres changed
  // (GpuProductPipeline::set_partial_frames); nothing: every texel may differ.
  std::optional<std::vector<terrain::PixelRect>> changed;
  std::uint64_t serial = 0;  // frame_on_gpu() calls of the renderer, this one included
};

class GpuRenderer final : public shading::Renderer {
 public:
  // Throws std::runtime_error ("no OpenGL 4.5 context could be created: …", one line).
  GpuRenderer();
  // On a context of the caller's (a window's: HeadlessContext(AdoptCurrentContext)).
  explicit GpuRenderer(std::unique_ptr<HeadlessContext> context);
  ~GpuRenderer() override;

  std::string description() const override;
  bool on_gpu() const override { return true; }
  void set_field(const terrain::HeightField& field) override { field_ = &field; }
  void set_options(const shading::ProductOptions& options) override;
  void expect_frames(int frames) override { keep_ = frames > 1; }
  void expect_blockers(bool expected) override { blockers_expected_ = expected; }
  void drop_horizons() override;
  void set_refresh_budget(std::size_t texels_per_frame) override { refresh_budget_ = texels_per_frame; }
  // GpuProductPipeline::set_sun_heading_tolerance for every frame's pipeline (the viewer's
  // frames and series: shading::kFrameSunTolerance); 0, the default, sweeps the sun
  // every frame.
  void set_sun_heading_tolerance(double radians) override { sun_heading_tolerance_ = radians; }
  // GpuProductPipeline::keep_sky_irradiance for every frame's pipeline (the viewer's).
  void keep_sky_irradiance(bool keep) { keep_sky_ = keep; }
  // GpuProductPipeline::set_partial_frames for every frame's pipeline (on by default).
  void set_partial_frames(bool partial) { partial_frames_ = partial; }
  std::optional<std::string> lacks_blockers(shading::Product product,
                                            const shading::ProductOptions& options) const override;
  std::optional<std::string> lacks(shading::Product product, const shading::ProductOptions& options) const override;
  bool fits_field(int width, int height, shading::Product product, const shading::ProductOptions& options) override;
  shading::ProductBands frame(shading::Product product, const shading::FrameInputs& inputs,
                              const shading::ProgressCallback& progress = {}) override;
  const shading::FrameTimings& last_timings() const override { return timings_; }
  // frame(), with the bands left on the GPU (no read-back).
  GpuFrame frame_on_gpu(shading::Product product, const shading::FrameInputs& inputs,
                        const shading::ProgressCallback& progress = {});

  const HeadlessContext& context() const { return *context_; }
  // The pipeline of the last frame (diagnostics: GpuProductPipeline::far_codes), or null.
  const GpuProductPipeline* last_pipeline() const { return last_; }

 private:
  struct Entry {
    shading::Product product;
    shading::ProductOptions options;
    bool blocked;  // built with sphere blockers
    std::unique_ptr<GpuProductPipeline> pipeline;
  };
  // Each pipeline holds its own copy of the field on the GPU: a few settings at most.
  static constexpr std::size_t kCachedPipelines = 4;
  GpuProductPipeline& pipeline_for(shading::Product product, const shading::ProductOptions& options, bool blocked);
  // Whether the frame takes a pipeline built with blockers: it has spheres that darken
  // the product, or blockers are expected and the product can take them.
  bool blocked_pipeline(shading::Product product, const shading::ProductOptions& options,
                        const shading::FrameInputs& inputs) const;
  // A frame's checks and options; resets the timings.
  shading::ProductOptions begin_frame(shading::Product product, const shading::FrameInputs& inputs);
  GpuProductPipeline& prepare(shading::Product product, const shading::ProductOptions& options,
                              const shading::FrameInputs& inputs);
  void finish_frame(std::chrono::steady_clock::time_point start);

  double context_ms_ = 0.0;                    // set by the context's construction, so declared before it
  std::unique_ptr<HeadlessContext> context_;  // destroyed after every GL object below
  bool context_reported_ = false;
  const terrain::HeightField* field_ = nullptr;
  shading::ProductOptions options_;
  bool keep_ = false;
  bool blockers_expected_ = false;
  std::size_t refresh_budget_ = 0;
  double sun_heading_tolerance_ = 0.0;
  bool keep_sky_ = false;
  bool partial_frames_ = true;
  int frames_ = 0;
  std::deque<Entry> cache_;
  const GpuProductPipeline* last_ = nullptr;
  const GpuProductPipeline* last_on_gpu_ = nullptr;  // whose buffer the last frame_on_gpu() returned
  std::uint64_t on_gpu_frames_ = 0;
  shading::FrameIndependentCache outputs_;
  shading::FrameTimings timings_;
};

}  // namespace skylit::gpu
