// Where `skylit bench` gets its frame times: a renderer (shading/renderer.h) of the
// backend, "auto" resolved once for the run, whose horizons are dropped before every
// frame so that each timed frame is a whole one. The reference is timed with a host
// clock around the frame; the gpu backend with its GL_TIME_ELAPSED queries
// (FrameTimings): sun + march + products, i.e. the GPU work of the product, without
// context creation, compilation, upload or read-back.
#pragma once

#include "shading/products.h"
#include "terrain/height_field.h"

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace skylit::app::bench {

// One computation's times, milliseconds.
struct FrameTime {
  double host_ms = 0;    // the source's host clock (wall or process CPU) around the call
  double wall_ms = 0;    // wall clock around the call (or compute()'s own wall_ms)
  std::optional<double> device_ms;  // GPU timer queries, where the backend has them
};

// The per-run milliseconds of one setting and the clock they were read from.
struct ClockedTimes {
  std::string clock;  // the CSV's `clock` column: "wall", "cpu", "gpu", "wall (llvmpipe: no GPU timer)"
  std::vector<double> ms;
};

class TimingSource {
 public:
  virtual ~TimingSource() = default;
  virtual std::string_view backend() const = 0;  // "gpu" or "reference" (auto resolved)
  virtual std::string clock() const = 0;         // the clock it asks for, for the banner
  // Why this backend cannot compute the product with these options (one line), or
  // nothing when it can. The bench skips such a setting rather than time another backend.
  virtual std::optional<std::string> lacks(shading::Product product, const shading::ProductOptions& options) const = 0;
  virtual shading::ProductBands compute(const terrain::HeightField& field, shading::Product product,
                                        const shading::ProductOptions& options, FrameTime& time) = 0;
  // The times of one setting's timed runs.
  virtual ClockedTimes frame_times(const std::vector<FrameTime>& runs) const = 0;
};

inline constexpr std::string_view kAutoClock = "auto", kWallClock = "wall", kCpuClock = "cpu", kGpuClock = "gpu";
// kAutoClock (the default: gpu on the gpu backend, else wall), kWallClock, kCpuClock, kGpuClock.
std::vector<std::string> clock_names();

// The backend of `backend`, "auto" resolved once for the whole run: gpu where a GL 4.5
// context can be created, else reference. Throws std::invalid_argument for an unknown
// backend or clock, or `gpu` clock on the reference; std::runtime_error for --backend
// gpu without a context.
std::unique_ptr<TimingSource> make_timing_source(const std::string& backend, const std::string& clock);

// True when the GPU timer reads ≈ 0 while compute() takes measurable wall time: Mesa
// llvmpipe runs compute dispatches on the CPU outside its GL_TIME_ELAPSED window.
bool gpu_timer_missing(const std::vector<FrameTime>& runs);

}  // namespace skylit::app::bench
