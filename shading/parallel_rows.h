// Rows of a raster spread over worker threads, with progress: what the CPU reference
// pipeline (reference_pipeline.h) and the sun's shadow field (sun_light.h) share.
#pragma once

#include <functional>

namespace skylit::shading {

// Fraction done in [0, 1]; called from worker threads, one call at a time.
using ProgressCallback = std::function<void(double fraction)>;

// Calls body(row) for every row in [0, rows) on `threads` workers (0 = hardware
// concurrency), reporting the fraction of rows done. The first exception thrown by
// a body stops the remaining rows and is rethrown here.
void parallel_rows(int rows, unsigned threads, const std::function<void(int row)>& body,
                   const ProgressCallback& progress = {});

}  // namespace skylit::shading
