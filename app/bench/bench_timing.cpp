#include "app/bench/bench_timing.h"

#include "gpu/renderer_factory.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <time.h>

namespace skylit::app::bench {
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

// Frames of one renderer, each a whole one (drop_horizons first). The renderer caches
// the compiled pipelines of the last few settings, so warm-up runs pay the compiles.
class RendererSource final : public TimingSource {
 public:
  RendererSource(std::unique_ptr<shading::Renderer> renderer, std::string_view host_clock)
      : renderer_(std::move(renderer)), host_clock_(host_clock) {}
  std::string_view backend() const override { return renderer_->on_gpu() ? "gpu" : "reference"; }
  std::string clock() const override {
    return renderer_->on_gpu() ? host_clock_ + " (" + renderer_name() + ")" : host_clock_;
  }
  std::optional<std::string> lacks(Product product, const shading::ProductOptions& options) const override {
    return renderer_->lacks(product, options);
  }
  shading::ProductBands compute(const terrain::HeightField& field, Product product,
                                const shading::ProductOptions& options, FrameTime& time) override {
    renderer_->set_field(field);
    renderer_->set_options(options);
    renderer_->drop_horizons();
    const double cpu0 = process_cpu_ms(), wall0 = wall_now_ms();
    auto bands = renderer_->frame(product, {options.lighting, {}, std::nullopt});
    const double wall = wall_now_ms() - wall0;
    const shading::FrameTimings& t = renderer_->last_timings();
    time.wall_ms = renderer_->on_gpu() && t.frame_ms > 0 ? t.frame_ms : wall;
    time.host_ms = host_clock_ == kCpuClock ? process_cpu_ms() - cpu0 : time.wall_ms;
    if (renderer_->on_gpu()) time.device_ms = t.sun_ms + t.march_ms + t.products_ms;
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
  // "llvmpipe" of "gpu (llvmpipe (LLVM 15.0.6, 256 bits), EGL surfaceless)".
  std::string renderer_name() const {
    const std::string d = renderer_->description();
    const std::size_t open = d.find('(');
    return open == std::string::npos ? d : d.substr(open + 1, d.find(' ', open) - open - 1);
  }

  std::unique_ptr<shading::Renderer> renderer_;
  std::string host_clock_;
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
  const auto backends = gpu::backend_names(), clocks = clock_names();
  const auto parsed = gpu::parse_backend(backend);
  if (!parsed) throw std::invalid_argument("unknown --backend '" + backend + "' (" + joined(backends) + ")");
  if (std::find(clocks.begin(), clocks.end(), clock) == clocks.end())
    throw std::invalid_argument("unknown --clock '" + clock + "' (" + joined(clocks) + ")");
  std::unique_ptr<shading::Renderer> renderer;
  if (*parsed != gpu::Backend::Reference) {
    try {
      renderer = gpu::make_renderer(gpu::Backend::Gpu);
    } catch (const std::runtime_error& e) {
      if (*parsed == gpu::Backend::Gpu) throw std::runtime_error("--backend gpu: " + one_line(e.what()));
    }
  }
  if (!renderer) {
    if (clock == kGpuClock) throw std::invalid_argument("--clock gpu needs the gpu backend (GPU timer queries)");
    return std::make_unique<RendererSource>(gpu::make_renderer(gpu::Backend::Reference), clock == kAutoClock ? kWallClock : clock);
  }
  return std::make_unique<RendererSource>(std::move(renderer), clock == kAutoClock ? kGpuClock : clock);
}

}  // namespace skylit::app::bench
