#include "shading/horizon/horizon_subsample.h"

namespace skylit::horizon {

terrain::PixelRect subsample_region(const terrain::HeightField& field, const terrain::PixelRect& region, int step) {
  const int first_x = std::max(region.x0, 0), last_x = std::min(region.x1(), field.width) - 1;
  const int first_y = std::max(region.y0, 0), last_y = std::min(region.y1(), field.height) - 1;
  if (region.empty() || step <= 1 || last_x < first_x || last_y < first_y) return region;  // nothing to grow
  const SubsampleAxis cols{field.width, step}, rows{field.height, step};
  const int x0 = cols.position(cols.bracket(first_x).c0), x1 = cols.position(cols.bracket(last_x).c1);
  const int y0 = rows.position(rows.bracket(first_y).c0), y1 = rows.position(rows.bracket(last_y).c1);
  return {x0, y0, x1 - x0 + 1, y1 - y0 + 1};
}

}  // namespace skylit::horizon
