#include "gpu/timer.h"

#include <epoxy/gl.h>

#include <stdexcept>

namespace skylit::gpu {

GpuTimer::GpuTimer() { glCreateQueries(GL_TIME_ELAPSED, 1, &mQuery); }

GpuTimer::~GpuTimer() {
  if (mActive) glEndQuery(GL_TIME_ELAPSED);
  glDeleteQueries(1, &mQuery);
}

void GpuTimer::begin() {
  if (mActive) throw std::logic_error("GpuTimer::begin: already running");
  glBeginQuery(GL_TIME_ELAPSED, mQuery);
  mActive = true;
}

void GpuTimer::end() {
  if (!mActive) throw std::logic_error("GpuTimer::end: not running");
  glEndQuery(GL_TIME_ELAPSED);
  mActive = false;
  mHasResult = true;
}

double GpuTimer::elapsed_ms() const {
  if (!mHasResult || mActive) throw std::logic_error("GpuTimer::elapsed_ms: no finished interval");
  GLuint64 ns = 0;
  glGetQueryObjectui64v(mQuery, GL_QUERY_RESULT, &ns);  // blocks until available
  return static_cast<double>(ns) * 1e-6;
}

}  // namespace skylit::gpu
