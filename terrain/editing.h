// Dynamic height fields: in-place edits of a sub-rectangle, and a window moving over a
// larger field (streaming). Every change bumps HeightField::revision and records the
// dirty rectangle, so derived data (HeightPyramid::update) never goes silently stale.
#pragma once

#include <span>
#include <stdexcept>

#include "terrain/height_field.h"

namespace skylit::terrain {

class EditError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Replaces heights in `rect` by `values` (rect.width·rect.height, row-major) and marks
// those texels valid. Throws EditError if rect is empty or not inside the field, if
// the size does not match, or if a value is not finite.
void replace_heights(HeightField& field, const PixelRect& rect, std::span<const float> values);

// Copy of `rect` of `source` as a field of its own: heights, valid, nodata, spacing
// (dx_per_row of those rows) and a geotransform shifted to the window's origin.
// Throws EditError if rect is empty or not inside the source.
HeightField extract_window(const HeightField& source, const PixelRect& rect);

// A fixed-size window moving over a larger field. The source must outlive the window.
// Each move copies the new window out and bumps the window field's revision, with the
// whole window as the dirty rectangle (its contents all changed place).
class MosaicWindow {
 public:
  MosaicWindow(const HeightField& source, int width, int height, int x0 = 0, int y0 = 0);

  // Moves the window's north-west texel to source texel (x0, y0); throws EditError if
  // the window would leave the source. No-op (no revision bump) if unchanged.
  void move_to(int x0, int y0);
  // Moves so that source texel (cx, cy) is as central as the source allows (clamped).
  void center_on(int cx, int cy);
  // Copies the source again (after the source itself was edited).
  void refresh();

  const HeightField& field() const { return window_; }
  PixelRect rect() const { return {x0_, y0_, window_.width, window_.height}; }

 private:
  const HeightField* source_;
  HeightField window_;
  int x0_ = 0, y0_ = 0;
};

}  // namespace skylit::terrain
