// `-p shaded --color FILE|RAMP`: the shaded relief's 8-bit bands blended with the colour
// relief of the same heights (shading/relief/tint_blend.h), on the host after any backend.
#pragma once

#include "shading/products.h"
#include "shading/relief/tint_blend.h"
#include "terrain/height_field.h"

#include <string>

namespace skylit::app::shade {

struct TintArgs {
  std::string color;  // file or ramp name
  relief::TintBlend blend = relief::TintBlend::SoftLight;
  double weight = 1.0;  // soft-light weight W
};

// "multiply", "soft-light" or "soft-light:W" (0 ≤ W ≤ 1); throws std::invalid_argument.
void parse_tint_blend(const std::string& text, TintArgs& out);
// R, G, B bands of `shaded` (1 or 3 code-value bands, NaN nodata) tinted by the colour table.
shading::ProductBands tint(const shading::ProductBands& shaded, const terrain::HeightField& field, const TintArgs& args);

}  // namespace skylit::app::shade
