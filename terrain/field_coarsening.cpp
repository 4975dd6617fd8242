#include "terrain/field_coarsening.h"

#include <stdexcept>

namespace skylit::terrain {

HeightField coarsen_by_two(const HeightField& f) {
  if (f.width < 2 || f.height < 2) throw std::invalid_argument("coarsen_by_two: a side is under 2 texels");
  HeightField c;
  c.width = f.width / 2;
  c.height = f.height / 2;
  c.heights.resize(static_cast<std::size_t>(c.width) * c.height);
  c.valid.resize(c.heights.size());
  c.dy = 2.0 * f.dy;
  c.dx_per_row.resize(c.height);
  for (int J = 0; J < c.height; ++J) {
    c.dx_per_row[J] = f.dx(2 * J) + f.dx(2 * J + 1);
    for (int I = 0; I < c.width; ++I) {
      double sum_valid = 0.0, sum_all = 0.0;
      int n_valid = 0;
      for (int dj = 0; dj < 2; ++dj)
        for (int di = 0; di < 2; ++di) {
          const int i = 2 * I + di, j = 2 * J + dj;
          sum_all += f.at(i, j);
          if (f.is_valid(i, j)) {
            sum_valid += f.at(i, j);
            ++n_valid;
          }
        }
      const std::size_t k = static_cast<std::size_t>(J) * c.width + I;
      c.heights[k] = static_cast<float>(n_valid > 0 ? sum_valid / n_valid : 0.25 * sum_all);
      c.valid[k] = n_valid > 0 ? 1 : 0;
    }
  }
  c.nodata = f.nodata;
  c.georef = f.georef;
  for (int k : {1, 2, 4, 5}) c.georef.geotransform[k] *= 2.0;
  c.mark_all_dirty();
  return c;
}

}  // namespace skylit::terrain
