// Compute backends of `shade`: the double-precision CPU reference, and the GLSL
// pipeline on the GPU (llvmpipe where no GPU exists).
#pragma once

#include "shading/products.h"

#include <string>
#include <vector>

namespace skylit::app {

// Names accepted by --backend, the default first.
std::vector<std::string> backend_names();
std::string default_backend();

// Throws std::invalid_argument for an unknown backend, std::runtime_error when the
// backend cannot run here (e.g. no OpenGL 4.5 context).
shading::ProductBands compute_with_backend(const std::string& backend, const terrain::HeightField& field,
                                           shading::Product product, const shading::ProductOptions& options,
                                           const shading::ProgressCallback& progress);

}  // namespace skylit::app
