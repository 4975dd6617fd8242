#include "app/view/window/viewer_panel.h"

#include <imgui.h>

#include <iterator>

#include "app/view/window/key_bindings.h"
#include "shading/sky/time_utc.h"
#include "view/terrain_lod.h"

namespace skylit::app::view::window {
namespace {

template <std::size_t N>
bool combo(const char* label, int& index, const char* const (&items)[N]) {
  return ImGui::Combo(label, &index, items, static_cast<int>(N));
}

void time_section(skylit::view::Timeline& t) {
  ImGui::Text("%s UTC", sky::format_utc_time({t.time()}).c_str());
  float offset = static_cast<float>(t.time() - t.start());
  if (ImGui::SliderFloat("time (s)", &offset, 0.0f, static_cast<float>(t.end() - t.start()), "%.1f"))
    t.scrub(t.start() + offset);
  if (ImGui::Button(t.playing() ? "pause" : "play")) t.toggle_playing();
  ImGui::SameLine();
  if (ImGui::Button("-")) t.slower();
  ImGui::SameLine();
  ImGui::Text("%gx", t.speed());
  ImGui::SameLine();
  if (ImGui::Button("+")) t.faster();
  ImGui::SameLine();
  bool reversed = t.reversed(), loop = t.looping();
  if (ImGui::Checkbox("reverse", &reversed)) t.toggle_reverse();
  ImGui::SameLine();
  if (ImGui::Checkbox("loop", &loop)) t.set_loop(loop);
}

void timing_section(const PanelInfo& info) {
  const skylit::view::ViewTimings& p = info.timings;
  ImGui::Text("frame %.1f ms (%.1f fps)", info.frame_ms, info.frame_ms > 0 ? 1000.0 / info.frame_ms : 0.0);
  ImGui::Text("shading %.1f ms%s", p.shading_ms, p.horizons_reused ? "" : " (horizons computed)");
  if (p.stale_texels > 0 && p.texels > 0)
    ImGui::Text("after the edit: %.0f%% of the field to refresh", 100.0 * p.stale_texels / p.texels);
  ImGui::Text("sky %.1f  terrain %.1f (%zu patches)  aircraft %.1f ms", p.sky_ms, p.terrain_ms, p.terrain_nodes,
              p.bodies_ms);
}

}  // namespace

void draw_panel(PanelState& s, skylit::view::Timeline& timeline, const PanelInfo& info) {
  s.screenshot = false;
  if (s.visible) {
    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.75f);
    ImGui::Begin("skylit", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    time_section(timeline);
    ImGui::Separator();
    ImGui::Text("sun azimuth %.1f, elevation %.1f deg", info.sun_azimuth_deg, info.sun_elevation_deg);
    combo("sky", s.sky, kSkyChoices);
    ImGui::SliderFloat("turbidity", &s.turbidity, 2.0f, 10.0f, "%.1f");
    combo("quality", s.quality, kQualityChoices);
    ImGui::SliderFloat("exaggeration", &s.exaggeration, 0.5f, 5.0f, "%.2f");
    ImGui::SliderFloat("mesh error (px)", &s.mesh_error_px, static_cast<float>(skylit::view::kMinMeshErrorPx), 8.0f, "%.1f");
    combo("camera", s.camera, kCameraChoices);
    combo("trail", s.trail, kTrailChoices);
    ImGui::Separator();
    combo("brush", s.brush, kBrushChoices);
    ImGui::SliderFloat("radius (m)", &s.brush_radius_m, 10.0f, 2000.0f, "%.0f");
    ImGui::SliderFloat("strength", &s.brush_strength, 0.0f, 100.0f, "%.1f");
    ImGui::SliderInt("screenshot scale", &s.screenshot_scale, 1, 8);
    s.screenshot = ImGui::Button("screenshot (F12)");
    ImGui::Separator();
    timing_section(info);
    ImGui::TextWrapped("%s", info.renderer.c_str());
    if (!info.tracks.empty()) ImGui::TextWrapped("%s", info.tracks.c_str());
    if (!info.note.empty()) ImGui::TextWrapped("note: %s", info.note.c_str());
    ImGui::Text("F1: keys");
    ImGui::End();
  }
  if (s.help) {
    ImGui::Begin("keys", &s.help, ImGuiWindowFlags_AlwaysAutoResize);
    for (const KeyBinding& b : key_bindings()) ImGui::Text("%-8.*s %.*s", static_cast<int>(b.key.size()), b.key.data(),
                                                         static_cast<int>(b.help.size()), b.help.data());
    ImGui::Text("%-8s %s", "wasd qe", "move (free camera), shift: faster");
    ImGui::Text("%-8s %s", "mouse", "right-drag: look / turn; wheel: zoom or speed");
    ImGui::End();
  }
}

}  // namespace skylit::app::view::window
