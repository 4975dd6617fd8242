#include "shading/local_products.h"

#include <stdexcept>
#include <string>

namespace skylit::shading {

ProductBands compute_local_product(const terrain::HeightField& field, Product product, const ProductOptions& options) {
  if (!traits(product).local)
    throw std::invalid_argument(std::string(product_name(product)) + " is not a local (3x3-window) product");
  ProductBands out;
  out.width = field.width;
  out.height = field.height;
  out.bands = 1;
  out.band_names = {std::string(product_name(product))};
  switch (product) {
    case Product::Hillshade: out.data = relief::gdal_hillshade(field, options.hillshade); break;
    default: throw std::logic_error("compute_local_product: no local computation for " + out.band_names.front());
  }
  return out;
}

}  // namespace skylit::shading
