#include "gpu/renderer_factory.h"

#include "gpu/gpu_renderer.h"
#include "shading/reference_renderer.h"

#include <stdexcept>

namespace skylit::gpu {
namespace {

using shading::Product;

// Backend::Auto: each frame on the GPU where it can, else on the reference. Both are made
// at their first use, so a run of host-side (local) products makes no GL context (on
// llvmpipe that is 0.1 s of a 0.2 s hillshade). Field, options and the frames hint go to
// both.
class AutoRenderer final : public shading::Renderer {
 public:
  explicit AutoRenderer(NoteCallback note) : note_(std::move(note)) {}
  std::string description() const override {
    if (last_on_gpu_) return gpu_->description();
    return "reference (CPU" + (why_reference_.empty() ? std::string() : "; " + why_reference_) + ")";
  }
  bool on_gpu() const override { return last_on_gpu_; }
  void set_field(const terrain::HeightField& field) override {
    field_ = &field;
    if (gpu_) gpu_->set_field(field);
    if (reference_) reference_->set_field(field);
  }
  void set_options(const shading::ProductOptions& options) override {
    options_ = options;
    if (gpu_) gpu_->set_options(options);
    if (reference_) reference_->set_options(options);
  }
  void expect_frames(int frames) override {
    frames_ = frames;
    if (gpu_) gpu_->expect_frames(frames);
    if (reference_) reference_->expect_frames(frames);
  }
  void expect_blockers(bool expected) override {
    blockers_expected_ = expected;
    if (gpu_) gpu_->expect_blockers(expected);
  }
  void set_refresh_budget(std::size_t texels_per_frame) override {
    refresh_budget_ = texels_per_frame;
    if (gpu_) gpu_->set_refresh_budget(texels_per_frame);
  }
  void set_sun_heading_tolerance(double radians) override {
    sun_heading_tolerance_ = radians;
    if (gpu_) gpu_->set_sun_heading_tolerance(radians);
  }
  void drop_horizons() override {
    if (gpu_) gpu_->drop_horizons();
    if (reference_) reference_->drop_horizons();
  }
  // On the reference where the GPU cannot.
  std::optional<std::string> lacks_blockers(Product, const shading::ProductOptions&) const override {
    return std::nullopt;
  }
  std::optional<std::string> lacks(Product, const shading::ProductOptions&) const override { return std::nullopt; }
  // The GPU's limits where the GPU would compute such frames.
  bool fits_field(int width, int height, Product product, const shading::ProductOptions& options) override {
    if (shading::traits(product).local) return true;
    make_gpu();
    if (!gpu_ || gpu_->lacks(product, options)) return true;
    return gpu_->fits_field(width, height, product, options);
  }
  shading::ProductBands frame(Product product, const shading::FrameInputs& inputs,
                              const shading::ProgressCallback& progress) override {
    const shading::ProductOptions options = shading::frame_options(options_, inputs);
    if (shading::traits(product).local) {  // host-side either way: no context for it
      why_reference_ = "";
      last_on_gpu_ = false;
      last_ = &reference();
      return reference().frame(product, inputs, progress);
    }
    make_gpu();
    const bool blocked = shading::blocked_frame(product, inputs);
    const std::optional<std::string> no_blockers =
        gpu_ && blocked ? gpu_->lacks_blockers(product, options) : std::nullopt;
    if (gpu_ && !gpu_->lacks(product, options) && !no_blockers) {
      try {
        auto bands = gpu_->frame(product, inputs, progress);
        last_on_gpu_ = true;
        last_ = gpu_.get();
        return bands;
      } catch (const std::invalid_argument&) {
        throw;  // bad options or inputs: the reference would refuse them too
      } catch (const std::runtime_error& e) {  // e.g. a field over the GPU's buffer limits
        if (note_) note_(std::string("the gpu backend failed (") + e.what() + "); computing with the reference backend");
        why_reference_ = "the gpu backend failed";
      }
    } else {
      why_reference_ = !gpu_          ? "no OpenGL 4.5 context"
                       : no_blockers ? *no_blockers
                                     : "the GPU pipeline lacks these options";
    }
    last_on_gpu_ = false;
    last_ = &reference();
    return reference().frame(product, inputs, progress);
  }
  const shading::FrameTimings& last_timings() const override { return last_ ? last_->last_timings() : none_; }

 private:
  void make_gpu() {
    if (gpu_tried_) return;
    gpu_tried_ = true;
    try {
      gpu_ = std::make_unique<GpuRenderer>();
    } catch (const std::runtime_error&) {  // no GL 4.5 here: every frame on the reference
      return;
    }
    if (field_) gpu_->set_field(*field_);
    gpu_->set_options(options_);
    gpu_->expect_frames(frames_);
    gpu_->expect_blockers(blockers_expected_);
    gpu_->set_refresh_budget(refresh_budget_);
    gpu_->set_sun_heading_tolerance(sun_heading_tolerance_);
  }
  shading::Renderer& reference() {
    if (!reference_) {
      reference_ = std::make_unique<shading::ReferenceRenderer>();
      if (field_) reference_->set_field(*field_);
      reference_->set_options(options_);
      reference_->expect_frames(frames_);
    }
    return *reference_;
  }

  NoteCallback note_;
  std::unique_ptr<GpuRenderer> gpu_;
  bool gpu_tried_ = false;
  std::unique_ptr<shading::ReferenceRenderer> reference_;
  const terrain::HeightField* field_ = nullptr;
  shading::ProductOptions options_;
  int frames_ = 1;
  bool blockers_expected_ = false;
  std::size_t refresh_budget_ = 0;
  double sun_heading_tolerance_ = 0.0;
  bool last_on_gpu_ = false;
  std::string why_reference_;
  const shading::Renderer* last_ = nullptr;
  shading::FrameTimings none_;
};

}  // namespace

std::vector<std::string> backend_names() { return {"auto", "gpu", "reference"}; }

std::string_view backend_name(Backend backend) {
  switch (backend) {
    case Backend::Auto: return "auto";
    case Backend::Gpu: return "gpu";
    case Backend::Reference: return "reference";
  }
  return "auto";
}

std::optional<Backend> parse_backend(std::string_view name) {
  for (Backend b : {Backend::Auto, Backend::Gpu, Backend::Reference})
    if (backend_name(b) == name) return b;
  return std::nullopt;
}

std::unique_ptr<shading::Renderer> make_renderer(Backend backend, NoteCallback note) {
  switch (backend) {
    case Backend::Gpu: return std::make_unique<GpuRenderer>();
    case Backend::Reference: return std::make_unique<shading::ReferenceRenderer>();
    case Backend::Auto: break;
  }
  return std::make_unique<AutoRenderer>(std::move(note));
}

}  // namespace skylit::gpu
