#include "terrain/editing.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace skylit::terrain {
namespace {

std::string describe(const PixelRect& r) {
  return std::to_string(r.width) + "×" + std::to_string(r.height) + " at (" + std::to_string(r.x0) + ", " +
         std::to_string(r.y0) + ")";
}

void check_inside(const PixelRect& r, int w, int h, const char* what) {
  if (r.empty()) throw EditError(std::string(what) + ": empty rectangle " + describe(r));
  if (r.x0 < 0 || r.y0 < 0 || r.x1() > w || r.y1() > h)
    throw EditError(std::string(what) + ": rectangle " + describe(r) + " is not inside the " + std::to_string(w) +
                    "×" + std::to_string(h) + " height field");
}

}  // namespace

void replace_heights(HeightField& field, const PixelRect& rect, std::span<const float> values) {
  check_inside(rect, field.width, field.height, "replace_heights");
  if (values.size() != static_cast<std::size_t>(rect.width) * rect.height)
    throw EditError("replace_heights: " + std::to_string(values.size()) + " values for a " +
                    std::to_string(rect.width) + "×" + std::to_string(rect.height) + " rectangle");
  if (!std::all_of(values.begin(), values.end(), [](float v) { return std::isfinite(v); }))
    throw EditError("replace_heights: values must be finite");
  for (int j = 0; j < rect.height; ++j)
    for (int i = 0; i < rect.width; ++i) {
      const std::size_t k = static_cast<std::size_t>(rect.y0 + j) * field.width + rect.x0 + i;
      field.heights[k] = values[static_cast<std::size_t>(j) * rect.width + i];
      field.valid[k] = 1;
    }
  field.mark_dirty(rect);
}

HeightField extract_window(const HeightField& src, const PixelRect& rect) {
  check_inside(rect, src.width, src.height, "extract_window");
  HeightField out;
  out.width = rect.width;
  out.height = rect.height;
  out.heights.resize(static_cast<std::size_t>(rect.width) * rect.height);
  out.valid.resize(out.heights.size());
  for (int j = 0; j < rect.height; ++j) {
    const std::size_t s = static_cast<std::size_t>(rect.y0 + j) * src.width + rect.x0;
    std::copy_n(src.heights.begin() + s, rect.width, out.heights.begin() + static_cast<std::size_t>(j) * rect.width);
    std::copy_n(src.valid.begin() + s, rect.width, out.valid.begin() + static_cast<std::size_t>(j) * rect.width);
  }
  out.dy = src.dy;
  out.dx_per_row.assign(src.dx_per_row.begin() + rect.y0, src.dx_per_row.begin() + rect.y1());
  out.nodata = src.nodata;
  out.georef = src.georef;
  auto& gt = out.georef.geotransform;  // north-up (the reader guarantees it)
  gt[0] += rect.x0 * gt[1] + rect.y0 * gt[2];
  gt[3] += rect.x0 * gt[4] + rect.y0 * gt[5];
  out.revision = 0;
  out.last_dirty = out.bounds();
  return out;
}

MosaicWindow::MosaicWindow(const HeightField& source, int width, int height, int x0, int y0)
    : source_(&source), x0_(x0), y0_(y0) {
  window_ = extract_window(source, {x0, y0, width, height});
}

void MosaicWindow::move_to(int x0, int y0) {
  if (x0 == x0_ && y0 == y0_) return;
  const PixelRect next{x0, y0, window_.width, window_.height};
  check_inside(next, source_->width, source_->height, "MosaicWindow::move_to");
  const std::uint64_t revision = window_.revision;
  window_ = extract_window(*source_, next);
  x0_ = x0;
  y0_ = y0;
  window_.revision = revision;
  window_.mark_all_dirty();
}

void MosaicWindow::center_on(int cx, int cy) {
  const int x0 = std::clamp(cx - window_.width / 2, 0, source_->width - window_.width);
  const int y0 = std::clamp(cy - window_.height / 2, 0, source_->height - window_.height);
  move_to(x0, y0);
}

void MosaicWindow::refresh() {
  const std::uint64_t revision = window_.revision;
  window_ = extract_window(*source_, rect());
  window_.revision = revision;
  window_.mark_all_dirty();
}

}  // namespace skylit::terrain
