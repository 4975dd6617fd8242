// The progress callback of the shading library's long calls: parallel/parallel_rows.h's.
#pragma once

#include "parallel/parallel_rows.h"

namespace skylit::shading {

using ProgressCallback = parallel::ProgressCallback;

}  // namespace skylit::shading
