#include "gpu/visibility_refresh.h"

#include <algorithm>
#include <stdexcept>

namespace skylit::gpu {
namespace {

std::size_t area(const terrain::PixelRect& r) {
  return r.empty() ? 0 : static_cast<std::size_t>(r.width) * static_cast<std::size_t>(r.height);
}

terrain::PixelRect clipped(int x0, int y0, int x1, int y1, const terrain::PixelRect& to) {
  x0 = std::max(x0, to.x0), y0 = std::max(y0, to.y0);
  x1 = std::min(x1, to.x1()), y1 = std::min(y1, to.y1());
  return {x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
}

}  // namespace

void VisibilityRefresh::reset(int width, int height) { bounds_ = current_ = {0, 0, width, height}; }

terrain::PixelRect VisibilityRefresh::edit(const terrain::PixelRect& dirty, int margin) {
  if (dirty.empty() || margin < 0) throw std::invalid_argument("VisibilityRefresh::edit: empty rectangle or negative margin");
  current_ = clipped(dirty.x0 - margin, dirty.y0 - margin, dirty.x1() + margin, dirty.y1() + margin, bounds_);
  if (current_.empty()) throw std::invalid_argument("VisibilityRefresh::edit: the rectangle lies outside the field");
  return current_;
}

terrain::PixelRect VisibilityRefresh::grown(int by) const {
  return clipped(current_.x0 - by, current_.y0 - by, current_.x1() + by, current_.y1() + by, bounds_);
}

std::vector<terrain::PixelRect> VisibilityRefresh::refine(std::size_t budget) {
  if (complete()) return {};
  // The smallest ring width adding ≥ budget texels: the added area grows with the width.
  const int most = std::max(bounds_.width, bounds_.height);
  int lo = 1, hi = most;
  while (lo < hi) {
    const int mid = lo + (hi - lo) / 2;
    if (area(grown(mid)) - area(current_) >= budget) hi = mid; else lo = mid + 1;
  }
  const terrain::PixelRect n = grown(lo), c = current_;
  std::vector<terrain::PixelRect> added;
  for (const terrain::PixelRect& r : {terrain::PixelRect{n.x0, n.y0, n.width, c.y0 - n.y0},          // north band
                                      terrain::PixelRect{n.x0, c.y1(), n.width, n.y1() - c.y1()},    // south band
                                      terrain::PixelRect{n.x0, c.y0, c.x0 - n.x0, c.height},         // west strip
                                      terrain::PixelRect{c.x1(), c.y0, n.x1() - c.x1(), c.height}})  // east strip
    if (!r.empty()) added.push_back(r);
  current_ = n;
  return added;
}

std::size_t VisibilityRefresh::stale_texels() const { return area(bounds_) - area(current_); }

}  // namespace skylit::gpu
