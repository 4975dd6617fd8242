#include "terrain/height_field.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace skylit::terrain {

HeightField::HeightField(int w, int h, double spacing)
    : width(w), height(h), heights(static_cast<std::size_t>(w) * h, 0.0f),
      valid(static_cast<std::size_t>(w) * h, 1), dy(spacing), dx_per_row(h, spacing) {
  if (w < 1 || h < 1) throw std::invalid_argument("HeightField: size must be positive");
  if (!(spacing > 0)) throw std::invalid_argument("HeightField: spacing must be positive");
  georef.geotransform = {0, spacing, 0, 0, 0, -spacing};
}

double HeightField::mean_dx() const {
  return dx_per_row.empty() ? dy
                            : std::accumulate(dx_per_row.begin(), dx_per_row.end(), 0.0) / dx_per_row.size();
}

bool HeightField::any_nodata() const {
  return std::any_of(valid.begin(), valid.end(), [](std::uint8_t v) { return v == 0; });
}

}  // namespace skylit::terrain
