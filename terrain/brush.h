// A terrain brush for dynamic height fields (the fly-through viewer's sculpting):
// raise, lower or smooth the heights under a disc, with a smooth compact falloff
//   w(r) = (1 − (r/R)²)²  for r < R, 0 beyond,
// so an application has no visible rim (w and w' vanish at r = R). Pure CPU; the change
// goes through HeightField::mark_dirty(), so the GPU renderer re-uploads only those rows.
#pragma once

#include "terrain/editing.h"
#include "terrain/height_field.h"

namespace skylit::terrain {

enum class BrushMode { Raise, Lower, Smooth };

struct Brush {
  BrushMode mode = BrushMode::Raise;
  double radius_m = 1.0;  // R, metres on the ground (> 0)
  // Raise / Lower: metres added / removed at the centre per application (≥ 0); a texel at
  //   distance r gets strength·w(r), so one application adds π R² strength / 3 of volume.
  // Smooth: in [0, 1], how far each texel moves toward its 3×3 mean per application (times
  //   w(r)); 1 at the centre replaces it by the mean.
  double strength = 1.0;
};

// Applies `brush` once, centred at field-frame position (x_m east, y_m north, metres;
// texel (i, j) is at (i·dx(j), −j·dy), see height_field.h). Texels with r < R are
// candidates; nodata texels are left alone (and Smooth does not read them). The brush may
// overlap the field's edges or lie outside it: it is clipped. Marks the bounding
// rectangle of the texels whose float value changed dirty (one revision bump) and returns
// it; when nothing changed it returns an empty rectangle and leaves the revision alone.
// Throws EditError if the radius is not positive and finite, the position is not finite,
// or the strength is not finite or outside its mode's range; the field is then unchanged.
PixelRect apply_brush(HeightField& field, const Brush& brush, double x_m, double y_m);

// A drag of the brush: one application where it starts, then one every `spacing` metres,
// each on the straight line from the previous application toward the position the brush
// was moved to, so a stroke along a line does not depend on how often its path is sampled
// (the frame rate). Each call that
// changes the field bumps its revision once, dirtying the bounding rectangle of all its
// applications. Positions are in the field frame, as apply_brush's.
class BrushStroke {
 public:
  // Throws EditError for a bad brush or a spacing that is not positive and finite.
  BrushStroke(const Brush& brush, double spacing_m);
  // The first application, at (x_m, y_m).
  PixelRect begin(HeightField& field, double x_m, double y_m);
  // Applications every `spacing` from the last one toward (x_m, y_m); the remainder of the
  // distance carries over to the next move (none when it is shorter than `spacing`).
  // Before begin(): begin(). If an application throws (float overflow), those before it
  // stay applied and dirty.
  PixelRect move_to(HeightField& field, double x_m, double y_m);
  int stamps() const { return stamps_; }

 private:
  Brush brush_;
  double spacing_;
  double last_x_ = 0.0, last_y_ = 0.0;  // the last application
  bool started_ = false;
  int stamps_ = 0;
};

}  // namespace skylit::terrain
