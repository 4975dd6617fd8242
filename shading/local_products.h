// The one place that computes the local products (ProductTraits::local): 3×3-window
// relief from the heights alone, on the host, whichever renderer is asked. A new local
// product adds its case here and its traits row; the renderers need no change.
#pragma once

#include "shading/products.h"

namespace skylit::shading {

// `product` (traits(product).local must hold) for every texel of `field`, one band named
// after the product; NaN where nodata. Throws std::invalid_argument for a non-local one.
ProductBands compute_local_product(const terrain::HeightField& field, Product product, const ProductOptions& options);

}  // namespace skylit::shading
