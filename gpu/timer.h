// GPU-side timing with GL_TIME_ELAPSED queries, for benchmarks: measures the time the
// GPU spent on the commands issued between begin() and end(), excluding CPU overhead.
// And the wall clock the stages are reported in where a driver has no GPU timer.
#pragma once

#include <chrono>
#include <cstdint>

namespace skylit::gpu {

// Wall-clock milliseconds since `start` (std::chrono::steady_clock).
inline double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

class GpuTimer {
 public:
  GpuTimer();  // needs a current context
  ~GpuTimer();
  GpuTimer(const GpuTimer&) = delete;
  GpuTimer& operator=(const GpuTimer&) = delete;

  // One begin/end pair at a time (GL allows one active TIME_ELAPSED query).
  void begin();
  void end();
  // Waits for the GPU to finish the timed commands; milliseconds. Throws
  // std::logic_error unless begin() and end() came first.
  double elapsed_ms() const;

 private:
  std::uint32_t mQuery = 0;
  bool mActive = false, mHasResult = false;
};

// Times a scope: begin() on construction, end() on destruction.
class ScopedGpuTimer {
 public:
  explicit ScopedGpuTimer(GpuTimer& timer) : mTimer(timer) { mTimer.begin(); }
  ~ScopedGpuTimer() { mTimer.end(); }
  ScopedGpuTimer(const ScopedGpuTimer&) = delete;
  ScopedGpuTimer& operator=(const ScopedGpuTimer&) = delete;

 private:
  GpuTimer& mTimer;
};

}  // namespace skylit::gpu
