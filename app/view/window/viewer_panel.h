// The viewer's Dear ImGui panel: time and speed, sun, sky and turbidity, quality preset,
// exaggeration, camera, brush, screenshot scale and the frame-time breakdown per pass;
// F1 shows the keys (key_bindings.h).
#pragma once

#include <string>
#include <vector>

#include "view/scene_view.h"
#include "view/terrain_lod.h"
#include "view/timeline.h"

namespace skylit::app::view::window {

inline constexpr const char* kSkyChoices[] = {"uniform", "preetham", "cie:1", "cie:12"};
inline constexpr const char* kQualityChoices[] = {"fast", "default", "high"};
inline constexpr const char* kCameraChoices[] = {"follow", "orbit", "free"};
inline constexpr const char* kBrushChoices[] = {"off", "raise", "lower", "smooth"};
inline constexpr const char* kTrailChoices[] = {"off", "altitude", "climb rate"};  // app::view::Trail's order

// What the user set; the viewer applies changes after the panel is drawn.
struct PanelState {
  int sky = 1;  // kSkyChoices
  float turbidity = 3.0f;
  int quality = 1;  // kQualityChoices
  float exaggeration = 1.0f;
  float mesh_error_px = static_cast<float>(skylit::view::kDefaultMeshErrorPx);
  int camera = 0;  // kCameraChoices
  int brush = 0;   // kBrushChoices
  int trail = 1;   // kTrailChoices
  float brush_radius_m = 200.0f, brush_strength = 20.0f;
  int screenshot_scale = 1;
  bool visible = true, help = false;
  bool screenshot = false;  // the button was pressed this frame
};

struct PanelInfo {
  double sun_azimuth_deg = 0.0, sun_elevation_deg = 0.0;
  skylit::view::ViewTimings timings;
  double frame_ms = 0.0;  // wall time of the whole last frame
  std::string renderer, tracks, note;
};

void draw_panel(PanelState& state, skylit::view::Timeline& timeline, const PanelInfo& info);

}  // namespace skylit::app::view::window
