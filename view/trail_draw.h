// Draws flight trails (view/trail_polyline.h; any number of tracks) as 1-pixel lines up
// to the playback time, into the bound framebuffer after the terrain, depth-tested as
// the caller set it (SceneView: GL_LESS). Needs a current GL 4.5 context.
#pragma once

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <span>
#include <vector>

#include "gpu/buffers.h"
#include "gpu/graphics_program.h"
#include "view/curvature_drop.h"
#include "view/trail_polyline.h"

namespace skylit::view {

// Wide enough to follow at 1280×720 (a 1-pixel line is lost against the relief).
inline constexpr double kTrailWidthPx = 3.0;

class TrailDraw {
 public:
  // Uploads the polylines once; they are drawn as they are (no gap is bridged).
  explicit TrailDraw(std::span<const TrailPolyline> polylines);
  ~TrailDraw();
  TrailDraw(const TrailDraw&) = delete;
  TrailDraw& operator=(const TrailDraw&) = delete;

  // Every polyline up to drawn_until_s (UTC), its last segment cut at that instant,
  // width_px pixels wide; z scaled by the exaggeration and lowered by the curvature drop
  // as the terrain and the aircraft are.
  void draw(const glm::dmat4& view_proj, double exaggeration, const CurvatureDrop& drop, double drawn_until_s,
            double width_px = kTrailWidthPx);

 private:
  gpu::GraphicsProgram program_;
  gpu::Buffer vertices_;
  std::vector<double> times_;  // per vertex, UTC: how much of each polyline to draw
  std::vector<std::int32_t> firsts_, ends_;  // per polyline: its vertices [first, end)
  std::vector<std::int32_t> segment_firsts_, counts_;  // per draw: its segments' vertices
  double time_origin_ = 0.0;  // the shader's times are float seconds after it
  std::uint32_t vao_ = 0;
};

}  // namespace skylit::view
