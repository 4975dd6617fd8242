// Compute backends of `shade`: the GLSL pipeline on the GPU (llvmpipe where no GPU
// exists; gpu/gpu_pipeline.h) and the double-precision CPU reference.
#pragma once

#include "gpu/gpu_pipeline.h"
#include "shading/products.h"

#include <string>
#include <vector>

namespace skylit::app {

// Names accepted by --backend, the default first:
//   auto       gpu where an OpenGL 4.5 context can be created and the GPU pipeline
//              has the product with these options (gpu::gpu_supports: every product;
//              the lit ones — shadow, irradiance, shaded with a sun or sky — not with
//              the exact march), else reference; also reference, with a note on stderr,
//              when the gpu backend fails at run time (e.g. over its buffer limits)
//   gpu        OpenGL 4.5 compute (an error where no context can be created)
//   reference  CPU, double precision
std::vector<std::string> backend_names();
std::string default_backend();

// What computed a product, and where the time went (`shade --timings`).
struct BackendReport {
  // e.g. "gpu (llvmpipe (LLVM 15.0.6, 256 bits), EGL surfaceless)" or
  // "reference (CPU; no OpenGL 4.5 context: …)".
  std::string used;
  bool on_gpu = false;
  double context_ms = 0.0;  // creating the OpenGL context (gpu)
  double compile_ms = 0.0;  // compiling and linking the pipeline's kernels (gpu)
  double compute_ms = 0.0;  // the product itself, read-back included
  gpu::GpuPipelineTimings gpu;  // the GPU pipeline's stages (on_gpu)
};

// Throws std::invalid_argument for an unknown backend or `gpu` with a product it does
// not have (message names the product and suggests reference/auto), std::runtime_error
// when the backend cannot run here ("--backend gpu: no OpenGL 4.5 context could be created: …",
// one line). `report`, if given, says what computed it and how long each part took.
shading::ProductBands compute_with_backend(const std::string& backend, const terrain::HeightField& field,
                                           shading::Product product, const shading::ProductOptions& options,
                                           const shading::ProgressCallback& progress, BackendReport* report = nullptr);

}  // namespace skylit::app
