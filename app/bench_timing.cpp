#include "app/bench_timing.h"

#include "app/backend.h"
#include "gpu/gl_context.h"
#include "gpu/gpu_pipeline.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <stdexcept>
#include <time.h>

namespace skylit::app {

// Options that give the same compiled pipeline: the bench varies only these fields.
bool same_pipeline_options(const shading::ProductOptions& a, const shading::ProductOptions& b) {
  return a.exact == b.exact && a.march.azimuths == b.march.azimuths && a.march.k_v == b.march.k_v &&
         a.march.level_offset == b.march.level_offset && a.march.use_pyramid == b.march.use_pyramid &&
         a.march.level_interpolation == b.march.level_interpolation && a.march.smooth_max == b.march.smooth_max &&
         a.march.method == b.march.method && a.march.sweep_near_steps == b.march.sweep_near_steps &&
         a.march.sweep_lines == b.march.sweep_lines &&
         a.shaded.sh_order == b.shaded.sh_order &&
         a.shaded.nlp_order == b.shaded.nlp_order && a.shaded.wedge == b.shaded.wedge &&
         a.subsample == b.subsample && a.exact_options.sky_azimuths == b.exact_options.sky_azimuths &&
         a.exact_options.step_texels == b.exact_options.step_texels;
}

namespace {

using shading::Product;

// Milliseconds on CLOCK_PROCESS_CPUTIME_ID: every thread of the process.
double process_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}
double wall_now_ms() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& n : names) text += (text.empty() ? "" : ", ") + n;
  return text;
}

double median_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The reference backend between two readings of a host clock.
class ReferenceSource final : public TimingSource {
 public:
  explicit ReferenceSource(bool cpu) : cpu_(cpu) {}
  std::string_view backend() const override { return "reference"; }
  std::string clock() const override { return std::string(cpu_ ? kCpuClock : kWallClock); }
  std::optional<std::string> lacks(Product, const shading::ProductOptions&) const override { return std::nullopt; }
  shading::ProductBands compute(const terrain::HeightField& field, Product product,
                                const shading::ProductOptions& options, FrameTime& time) override {
    const double cpu0 = process_cpu_ms(), wall0 = wall_now_ms();
    auto bands = shading::compute_product(field, product, options, {});
    time.wall_ms = wall_now_ms() - wall0;
    time.host_ms = cpu_ ? process_cpu_ms() - cpu0 : time.wall_ms;
    return bands;
  }
  ClockedTimes frame_times(const std::vector<FrameTime>& runs) const override {
    ClockedTimes t{clock(), {}};
    for (const FrameTime& r : runs) t.ms.push_back(r.host_ms);
    return t;
  }

 private:
  bool cpu_;
};

// One context for the run; pipelines compiled once per (product, setting) and kept
// while the sweep is on that setting. The cache is small because a pipeline keeps its
// field resident on the GPU: a 4096² scene's buffers per pipeline, times a sweep's
// settings, would not fit.
class GpuSource final : public TimingSource {
 public:
  GpuSource(std::unique_ptr<gpu::HeadlessContext> context, std::string_view host_clock)
      : context_(std::move(context)), host_clock_(host_clock) {}
  ~GpuSource() override {
    context_->make_current();  // GL objects die while their context is current
    cache_.clear();
  }
  std::string_view backend() const override { return "gpu"; }
  std::string clock() const override { return host_clock_ + " (" + context_->renderer() + ")"; }
  std::optional<std::string> lacks(Product product, const shading::ProductOptions& options) const override {
    if (gpu::gpu_supports(product, options)) return std::nullopt;
    return "the GPU pipeline lacks " + std::string(shading::product_name(product)) +
           " with these options (gpu::gpu_supports)";
  }
  shading::ProductBands compute(const terrain::HeightField& field, Product product,
                                const shading::ProductOptions& options, FrameTime& time) override {
    context_->make_current();  // another context (e.g. a gpu truth) may have been made current
    const gpu::GpuProductPipeline& pipeline = pipeline_for(product, options);
    gpu::GpuPipelineTimings t;
    const double cpu0 = process_cpu_ms(), wall0 = wall_now_ms();
    auto bands = pipeline.compute(field, {}, &t);
    const double wall = wall_now_ms() - wall0;
    time.wall_ms = t.wall_ms > 0 ? t.wall_ms : wall;
    time.host_ms = host_clock_ == kCpuClock ? process_cpu_ms() - cpu0 : time.wall_ms;
    time.device_ms = t.sun_ms + t.march_ms + t.products_ms;
    return bands;
  }
  ClockedTimes frame_times(const std::vector<FrameTime>& runs) const override {
    ClockedTimes t{host_clock_, {}};
    const bool gpu_clock = host_clock_ == kGpuClock;
    const bool missing = gpu_clock && gpu_timer_missing(runs);
    if (missing) t.clock = std::string(kWallClock) + " (" + renderer_name() + ": no GPU timer)";
    for (const FrameTime& r : runs) t.ms.push_back(gpu_clock && !missing ? *r.device_ms : r.host_ms);
    return t;
  }

 private:
  struct Entry {
    Product product;
    shading::ProductOptions options;
    std::unique_ptr<gpu::GpuProductPipeline> pipeline;
  };
  static constexpr std::size_t kCachedPipelines = 4;  // a setting's shaded + skyview, and the truth's

  const gpu::GpuProductPipeline& pipeline_for(Product product, const shading::ProductOptions& options) {
    const auto it = std::find_if(cache_.begin(), cache_.end(), [&](const Entry& e) {
      return e.product == product && same_pipeline_options(e.options, options);
    });
    if (it != cache_.end()) return *it->pipeline;
    if (cache_.size() == kCachedPipelines) cache_.pop_front();  // the oldest setting
    cache_.push_back({product, options, std::make_unique<gpu::GpuProductPipeline>(product, options)});
    return *cache_.back().pipeline;
  }
  // "llvmpipe" of "llvmpipe (LLVM 15.0.6, 256 bits)".
  std::string renderer_name() const {
    const std::string& r = context_->renderer();
    return r.substr(0, r.find(' '));
  }

  std::unique_ptr<gpu::HeadlessContext> context_;  // declared first: destroyed last
  std::string host_clock_;
  std::deque<Entry> cache_;
};

// One line: EGL explains each platform's failure on its own lines.
std::string one_line(std::string text) {
  std::replace_if(text.begin(), text.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
  return text;
}

}  // namespace

std::vector<std::string> clock_names() {
  return {std::string(kAutoClock), std::string(kWallClock), std::string(kCpuClock), std::string(kGpuClock)};
}

bool gpu_timer_missing(const std::vector<FrameTime>& runs) {
  std::vector<double> device, wall;
  for (const FrameTime& r : runs) {
    if (!r.device_ms) return true;
    device.push_back(*r.device_ms);
    wall.push_back(r.wall_ms);
  }
  if (runs.empty()) return true;
  // A real GPU's march alone is a sizeable part of compute(); llvmpipe reads 0–µs.
  constexpr double kTimerFloorOfWall = 1e-3;
  return median_of(device) <= kTimerFloorOfWall * median_of(wall);
}

std::unique_ptr<TimingSource> make_timing_source(const std::string& backend, const std::string& clock) {
  const auto backends = backend_names(), clocks = clock_names();
  if (std::find(backends.begin(), backends.end(), backend) == backends.end())
    throw std::invalid_argument("unknown --backend '" + backend + "' (" + joined(backends) + ")");
  if (std::find(clocks.begin(), clocks.end(), clock) == clocks.end())
    throw std::invalid_argument("unknown --clock '" + clock + "' (" + joined(clocks) + ")");
  std::unique_ptr<gpu::HeadlessContext> context;
  if (backend != "reference") {
    try {
      context = std::make_unique<gpu::HeadlessContext>();
    } catch (const std::exception& e) {
      if (backend == "gpu") throw std::runtime_error("--backend gpu: " + one_line(e.what()));
    }
  }
  if (!context) {
    if (clock == kGpuClock) throw std::invalid_argument("--clock gpu needs the gpu backend (GPU timer queries)");
    return std::make_unique<ReferenceSource>(clock == kCpuClock);
  }
  return std::make_unique<GpuSource>(std::move(context), clock == kAutoClock ? kGpuClock : clock);
}

}  // namespace skylit::app
