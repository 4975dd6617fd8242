#include "app/backend.h"

#include <stdexcept>

namespace skylit::app {

std::vector<std::string> backend_names() { return {"reference"}; }

std::string default_backend() { return backend_names().front(); }

shading::ProductBands compute_with_backend(const std::string& backend, const terrain::HeightField& field,
                                           shading::Product product, const shading::ProductOptions& options,
                                           const shading::ProgressCallback& progress) {
  if (backend == "reference") return shading::compute_product(field, product, options, progress);
  std::string known;
  for (const auto& b : backend_names()) known += (known.empty() ? "" : ", ") + b;
  throw std::invalid_argument("--backend '" + backend + "' is not available; this build has: " + known);
}

}  // namespace skylit::app
