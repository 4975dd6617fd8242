// Rows of a raster (or any numbered items) spread over worker threads, with progress:
// the CPU reference pipeline and sun shadow, the sweep's lines, the pyramid's rows and
// the tiles share it.
#pragma once

#include <functional>

namespace skylit::parallel {

// Fraction done in [0, 1]; called from worker threads, one call at a time.
using ProgressCallback = std::function<void(double fraction)>;

// Calls body(row) for every row in [0, rows) on `threads` workers (0 = hardware
// concurrency), reporting the fraction of rows done. The first exception thrown by
// a body stops the remaining rows and is rethrown here.
void parallel_rows(int rows, unsigned threads, const std::function<void(int row)>& body,
                   const ProgressCallback& progress = {});

}  // namespace skylit::parallel
