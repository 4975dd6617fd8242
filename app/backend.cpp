#include "app/backend.h"

#include "gpu/gl_context.h"
#include "gpu/gpu_pipeline.h"
#include "gpu/timer.h"

#include <chrono>
#include <iostream>
#include <memory>
#include <stdexcept>

namespace skylit::app {
namespace {

// One line: EGL explains each platform's failure on its own lines.
std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

std::unique_ptr<gpu::HeadlessContext> try_context(std::string* why) {
  try {
    return std::make_unique<gpu::HeadlessContext>();
  } catch (const std::exception& e) {
    if (why) *why = one_line(e.what());
    return nullptr;
  }
}

shading::ProductBands run_gpu(const gpu::HeadlessContext& context, const terrain::HeightField& field,
                              shading::Product product, const shading::ProductOptions& options,
                              const shading::ProgressCallback& progress, BackendReport& report) {
  context.make_current();
  const auto compile_start = std::chrono::steady_clock::now();
  const gpu::GpuProductPipeline pipeline(product, options);  // destroyed while current
  report.compile_ms = gpu::ms_since(compile_start);
  const auto compute_start = std::chrono::steady_clock::now();
  auto bands = pipeline.compute(field, progress, &report.gpu);
  report.compute_ms = gpu::ms_since(compute_start);
  report.on_gpu = true;
  return bands;
}

}  // namespace

std::vector<std::string> backend_names() { return {"auto", "gpu", "reference"}; }

std::string default_backend() { return backend_names().front(); }

shading::ProductBands compute_with_backend(const std::string& backend, const terrain::HeightField& field,
                                           shading::Product product, const shading::ProductOptions& options,
                                           const shading::ProgressCallback& progress, BackendReport* report) {
  BackendReport local;
  BackendReport& r = report ? *report : local;
  r = {};
  const auto reference = [&](const std::string& why) {
    r.used = "reference (CPU" + (why.empty() ? std::string() : "; " + why) + ")";
    r.on_gpu = false;
    const auto start = std::chrono::steady_clock::now();
    auto bands = shading::compute_product(field, product, options, progress);
    r.compute_ms = gpu::ms_since(start);
    return bands;
  };
  if (backend == "reference") return reference("");
  if ((backend == "gpu" || backend == "auto") && !gpu::gpu_supports(product, options)) {
    if (backend == "auto") return reference("the GPU pipeline lacks these options");
    throw std::invalid_argument("--backend gpu cannot compute '" + std::string(shading::product_name(product)) + "'" +
                                (options.exact && shading::uses_lighting(product, options)
                                     ? std::string(" with --exact (the sun's exact march is CPU-only)")
                                     : std::string(" with these options")) +
                                "; use --backend reference (or auto)");
  }
  if (backend == "gpu" || backend == "auto") {
    std::string why;
    const auto context_start = std::chrono::steady_clock::now();
    const auto context = try_context(&why);
    r.context_ms = gpu::ms_since(context_start);
    if (!context) {
      if (backend == "gpu") throw std::runtime_error("--backend gpu: " + why);
      return reference("no OpenGL 4.5 context");  // auto: no GL 4.5 here
    }
    r.used = "gpu (" + context->renderer() + ", " + context->platform() + ")";
    if (backend == "gpu") return run_gpu(*context, field, product, options, progress, r);
    try {
      return run_gpu(*context, field, product, options, progress, r);
    } catch (const std::runtime_error& e) {  // e.g. a field over the GPU's buffer limits
      std::cerr << "skylit: note: the gpu backend failed (" << one_line(e.what())
                << "); computing with the reference backend\n";
      return reference("the gpu backend failed");
    }
  }
  std::string known;
  for (const auto& b : backend_names()) known += (known.empty() ? "" : ", ") + b;
  throw std::invalid_argument("--backend '" + backend + "' is not available; this build has: " + known);
}

}  // namespace skylit::app
