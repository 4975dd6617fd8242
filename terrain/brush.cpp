#include "terrain/brush.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace skylit::terrain {
namespace {

// Clamped before the cast: a far-off (but finite) position must not overflow int.
int clamp_index(double v, int lo, int hi) { return static_cast<int>(std::clamp(v, double(lo), double(hi))); }

void check(const Brush& b, double x, double y) {
  const auto fail = [](const std::string& what) { throw EditError("apply_brush: " + what); };
  if (!std::isfinite(b.radius_m) || b.radius_m <= 0)
    fail("radius must be positive and finite (got " + std::to_string(b.radius_m) + " m)");
  if (!std::isfinite(x) || !std::isfinite(y)) fail("position must be finite");
  if (!std::isfinite(b.strength)) fail("strength must be finite");
  if (b.mode == BrushMode::Smooth && (b.strength < 0 || b.strength > 1))
    fail("smooth strength must be in [0, 1] (got " + std::to_string(b.strength) + ")");
  if (b.mode != BrushMode::Smooth && b.strength < 0)
    fail("raise/lower strength must be ≥ 0 (got " + std::to_string(b.strength) + " m); use the other mode");
}

// One application without the revision bump: returns the changed texels' bounding rectangle.
PixelRect stamp(HeightField& f, const Brush& brush, double x, double y) {
  const double R = brush.radius_m, R2 = R * R;
  // Rows and columns within R, one texel wider than needed: the exact r < R test decides.
  const int j0 = clamp_index(std::floor((-y - R) / f.dy) - 1, 0, f.height);
  const int j1 = clamp_index(std::ceil((-y + R) / f.dy) + 2, 0, f.height);
  int i0 = f.width, i1 = 0;
  for (int j = j0; j < j1; ++j) {
    i0 = std::min(i0, clamp_index(std::floor((x - R) / f.dx(j)) - 1, 0, f.width));
    i1 = std::max(i1, clamp_index(std::ceil((x + R) / f.dx(j)) + 2, 0, f.width));
  }
  if (j0 >= j1 || i0 >= i1) return {};
  const PixelRect box{i0, j0, i1 - i0, j1 - j0};
  const auto bidx = [&](int i, int j) { return static_cast<std::size_t>(j - j0) * box.width + (i - i0); };

  // Smooth reads a 3×3 mean of the original heights (copied, so the result does not depend
  // on traversal order). Separable, and a tap pair is used only when both sides exist and
  // are valid: symmetric taps keep a plane exactly, also at edges and next to nodata.
  std::vector<double> row_mean;  // rows j0−1 … j1 (clipped), columns of box
  const int r0 = std::max(j0 - 1, 0), r1 = std::min(j1 + 1, f.height);
  const auto ridx = [&](int i, int j) { return static_cast<std::size_t>(j - r0) * box.width + (i - i0); };
  if (brush.mode == BrushMode::Smooth) {
    row_mean.resize(static_cast<std::size_t>(r1 - r0) * box.width);
    for (int j = r0; j < r1; ++j)
      for (int i = i0; i < i1; ++i) {
        const bool pair = i > 0 && i + 1 < f.width && f.is_valid(i - 1, j) && f.is_valid(i + 1, j);
        row_mean[ridx(i, j)] =
            pair ? (double(f.at(i - 1, j)) + f.at(i, j) + f.at(i + 1, j)) / 3.0 : double(f.at(i, j));
      }
  }

  // New values into a buffer first, so a non-finite result throws with the field unchanged.
  std::vector<float> out(static_cast<std::size_t>(box.width) * box.height);
  for (int j = j0; j < j1; ++j) {
    const double ry = -j * f.dy - y;
    for (int i = i0; i < i1; ++i) {
      const double h = f.at(i, j), rx = i * f.dx(j) - x, q = (rx * rx + ry * ry) / R2;
      float& o = out[bidx(i, j)];
      o = static_cast<float>(h);
      if (q >= 1 || !f.is_valid(i, j)) continue;
      const double w = (1 - q) * (1 - q);
      switch (brush.mode) {
        case BrushMode::Raise: o = static_cast<float>(h + brush.strength * w); break;
        case BrushMode::Lower: o = static_cast<float>(h - brush.strength * w); break;
        case BrushMode::Smooth: {
          const bool pair = j > 0 && j + 1 < f.height && f.is_valid(i, j - 1) && f.is_valid(i, j + 1);
          const double mean =
              pair ? (row_mean[ridx(i, j - 1)] + row_mean[ridx(i, j)] + row_mean[ridx(i, j + 1)]) / 3.0
                   : row_mean[ridx(i, j)];
          o = static_cast<float>(h + brush.strength * w * (mean - h));
          break;
        }
      }
      if (!std::isfinite(o)) throw EditError("apply_brush: the result overflows float (strength too large)");
    }
  }

  // Commit, and dirty exactly the bounding rectangle of the texels that changed.
  int cx0 = i1, cx1 = i0, cy0 = j1, cy1 = j0;
  for (int j = j0; j < j1; ++j)
    for (int i = i0; i < i1; ++i) {
      const float v = out[bidx(i, j)];
      if (v == f.at(i, j)) continue;
      f.at(i, j) = v;
      cx0 = std::min(cx0, i), cx1 = std::max(cx1, i + 1), cy0 = std::min(cy0, j), cy1 = std::max(cy1, j + 1);
    }
  if (cx0 >= cx1) return {};
  return {cx0, cy0, cx1 - cx0, cy1 - cy0};
}

}  // namespace

PixelRect apply_brush(HeightField& f, const Brush& brush, double x, double y) {
  check(brush, x, y);
  const PixelRect changed = stamp(f, brush, x, y);
  if (!changed.empty()) f.mark_dirty(changed);
  return changed;
}

BrushStroke::BrushStroke(const Brush& brush, double spacing_m) : brush_(brush), spacing_(spacing_m) {
  check(brush, 0.0, 0.0);
  if (!std::isfinite(spacing_m) || spacing_m <= 0)
    throw EditError("BrushStroke: spacing must be positive and finite (got " + std::to_string(spacing_m) + " m)");
}

PixelRect BrushStroke::begin(HeightField& f, double x, double y) {
  check(brush_, x, y);
  last_x_ = x, last_y_ = y, started_ = true;
  stamps_ = 1;
  const PixelRect changed = stamp(f, brush_, x, y);
  if (!changed.empty()) f.mark_dirty(changed);
  return changed;
}

PixelRect BrushStroke::move_to(HeightField& f, double x, double y) {
  if (!started_) return begin(f, x, y);
  check(brush_, x, y);
  const double dx = x - last_x_, dy = y - last_y_, length = std::hypot(dx, dy);
  const int n = static_cast<int>(std::floor(length / spacing_));
  if (n == 0) return {};
  // Every stamp on the straight line from the last one: the same points however the
  // path was cut into moves.
  PixelRect changed;
  const double ux = dx / length, uy = dy / length;
  try {
    for (int k = 1; k <= n; ++k) {
      changed = bounding_union(changed, stamp(f, brush_, last_x_ + k * spacing_ * ux, last_y_ + k * spacing_ * uy));
      ++stamps_;
    }
  } catch (const EditError&) {  // the applications before the failing one stay, tracked
    if (!changed.empty()) f.mark_dirty(changed);
    throw;
  }
  last_x_ += n * spacing_ * ux;
  last_y_ += n * spacing_ * uy;
  if (!changed.empty()) f.mark_dirty(changed);
  return changed;
}

}  // namespace skylit::terrain
