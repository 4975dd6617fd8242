#include "terrain/height_field.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace skylit::terrain {

PixelRect bounding_union(const PixelRect& a, const PixelRect& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  const int x0 = std::min(a.x0, b.x0), y0 = std::min(a.y0, b.y0);
  return {x0, y0, std::max(a.x1(), b.x1()) - x0, std::max(a.y1(), b.y1()) - y0};
}

HeightField::HeightField(int w, int h, double spacing)
    : width(w), height(h), heights(static_cast<std::size_t>(w) * h, 0.0f),
      valid(static_cast<std::size_t>(w) * h, 1), dy(spacing), dx_per_row(h, spacing) {
  if (w < 1 || h < 1) throw std::invalid_argument("HeightField: size must be positive");
  if (!(spacing > 0)) throw std::invalid_argument("HeightField: spacing must be positive");
  georef.geotransform = {0, spacing, 0, 0, 0, -spacing};
  last_dirty = bounds();
}

double HeightField::mean_dx() const {
  return dx_per_row.empty() ? dy
                            : std::accumulate(dx_per_row.begin(), dx_per_row.end(), 0.0) / dx_per_row.size();
}

bool HeightField::any_nodata() const {
  return std::any_of(valid.begin(), valid.end(), [](std::uint8_t v) { return v == 0; });
}

bool HeightField::one_edit_since(std::uint64_t since_revision) const {
  const PixelRect& d = last_dirty;
  return revision == since_revision + 1 && !d.empty() && d.x0 >= 0 && d.y0 >= 0 && d.x1() <= width && d.y1() <= height;
}

void HeightField::mark_dirty(const PixelRect& rect) {
  const int x0 = std::max(rect.x0, 0), y0 = std::max(rect.y0, 0);
  const int x1 = std::min(rect.x1(), width), y1 = std::min(rect.y1(), height);
  last_dirty = (x1 > x0 && y1 > y0) ? PixelRect{x0, y0, x1 - x0, y1 - y0} : PixelRect{};
  ++revision;
}

}  // namespace skylit::terrain
