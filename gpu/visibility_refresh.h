// Which texels of a kept visibility to recompute after an edit of the height field (the
// viewer's brush), so that an edit costs its own area at once and the rest of the field
// catches up over the next frames, nearest the edit first.
//
// An edit changes the horizons of texels far from it (a raised hill is seen from
// anywhere along the march), so recomputing near the edit alone would leave the rest
// wrong for good. Instead the current region starts as the edit's rectangle grown by a
// margin and grows by whole rings (Chebyshev distance from the edit) each frame, until it
// holds the field: then every texel is again exactly what a whole recompute would give.
// A second edit before that restarts from its own rectangle: texels outside it are stale
// for it anyway.
#pragma once

#include <cstddef>
#include <vector>

#include "terrain/height_field.h"

namespace skylit::gpu {

class VisibilityRefresh {
 public:
  // Every texel of a width × height field current.
  void reset(int width, int height);
  // The field changed in `dirty` (inside the field): returns the texels to recompute now
  // (`dirty` grown by `margin` on each side, clipped); the rest are stale.
  terrain::PixelRect edit(const terrain::PixelRect& dirty, int margin);
  // Grows the current region by the fewest whole rings that add at least `budget`
  // texels (or all that are left) and returns the added texels as up to four disjoint
  // rectangles; none when complete.
  std::vector<terrain::PixelRect> refine(std::size_t budget);

  bool complete() const { return current_ == bounds_; }
  const terrain::PixelRect& current() const { return current_; }
  std::size_t stale_texels() const;

 private:
  terrain::PixelRect grown(int by) const;
  terrain::PixelRect bounds_, current_;
};

}  // namespace skylit::gpu
