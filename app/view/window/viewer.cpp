#include "app/view/window/viewer.h"

#include <epoxy/gl.h>
#include <GLFW/glfw3.h>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <iostream>
#include <memory>
#include <optional>

#include "app/common/altitude_arg.h"
#include "app/common/date_daylight.h"
#include "app/common/synthetic_scene.h"
#include "app/shade/tracked_aircraft.h"
#include "app/view/aircraft_trails.h"
#include "app/view/mesh_error.h"
#include "app/view/camera_aim.h"
#include "app/view/window/glfw_window.h"
#include "app/view/window/key_bindings.h"
#include "app/view/window/screenshot.h"
#include "app/view/window/view_script.h"
#include "app/view/window/viewer_panel.h"
#include "gpu/gpu_renderer.h"
#include "shading/quality.h"
#include "shading/time_series.h"
#include "terrain/brush.h"
#include "terrain/field_coarsening.h"
#include "view/camera.h"
#include "view/offscreen_target.h"
#include "view/scene_view.h"
#include "view/lighting_reuse.h"
#include "view/timeline.h"
#include "view/trail_draw.h"

namespace skylit::app::view::window {
namespace {

namespace sv = skylit::view;

constexpr double kLookRadPerPixel = 0.004;
constexpr double kSecondsPerDay = 86400.0;

template <std::size_t N>
int index_of(const char* const (&items)[N], const std::string& name) {
  for (std::size_t k = 0; k < N; ++k)
    if (name == items[k]) return static_cast<int>(k);
  return -1;
}

// The local solar day (by longitude) around t, for a clock with no track.
std::pair<double, double> local_day(double t, double longitude_deg) {
  const double shift = longitude_deg / 360.0 * kSecondsPerDay;
  const double start = std::floor((t + shift) / kSecondsPerDay) * kSecondsPerDay - shift;
  return {start, start + kSecondsPerDay};
}

// A script's `pose X Y Z HEADING PITCH`: the eye in the field frame, the view's heading
// (degrees clockwise from north) and pitch (degrees up).
sv::CameraPose script_pose(const ScriptEvent& e) {
  const double h = glm::radians(e.heading_deg), p = glm::radians(e.pitch_deg);
  sv::CameraPose pose;
  pose.eye = e.eye;
  pose.forward = sv::direction(h, p);
  const glm::dvec3 right{std::cos(h), -std::sin(h), 0.0};
  pose.up = glm::normalize(glm::cross(right, pose.forward));
  return pose;
}

sv::CameraInput camera_input(const InputState& input) {
  auto axis = [&](const char* plus, const char* minus) {
    return (input.is_held(plus) ? 1.0 : 0.0) - (input.is_held(minus) ? 1.0 : 0.0);
  };
  sv::CameraInput in;
  in.move = {axis("d", "a"), axis("w", "s"), axis("e", "q")};
  in.yaw_rad = input.look.x * kLookRadPerPixel;
  in.pitch_rad = -input.look.y * kLookRadPerPixel;
  in.zoom = input.wheel;
  in.fast = input.is_held("shift");
  return in;
}

// Every check of the options that needs neither the DEM nor a window, so bad input
// fails in one line before either is opened.
const ViewerOptions& checked(const ViewerOptions& o) {
  if (!(o.exaggeration > 0.0) || o.exaggeration > 100.0) throw std::invalid_argument("--exaggeration must be in (0, 100]");
  check_mesh_error(o.mesh_error_px);
  if (!(o.fps > 0.0)) throw std::invalid_argument("--fps must be > 0");
  if (o.frames > 0 && o.screenshot.empty()) throw std::invalid_argument("--frames needs --screenshot FILE");
  if (!o.screenshot.empty()) check_screenshot_path(o.screenshot, o.overwrite);
  if (o.screenshot_scale < 1 || o.screenshot_scale > 16) throw std::invalid_argument("--screenshot-scale must be 1 to 16");
  if (o.refresh_frames < 0 || o.refresh_frames > 1000) throw std::invalid_argument("--refresh-frames must be 0 to 1000");
  if (!shading::parse_quality(o.quality))
    throw std::invalid_argument("--quality '" + o.quality + "' is not fast, default or high");
  if (!sv::parse_camera_mode(o.camera)) throw std::invalid_argument("--camera '" + o.camera + "' is not follow, orbit or free");
  return o;
}

class Viewer {
 public:
  explicit Viewer(const ViewerOptions& o);
  int run();

 private:
  void load_aircraft();
  // The ground under the cameras, at the exaggeration of the moment.
  sv::GroundHeight ground() {
    return [this](double x, double y) { return sv::ground_of(field_, exaggeration_)(x, y); };
  }
  void fit_to_gpu();
  void apply_actions();
  void apply_panel();
  void apply_brush();
  std::optional<glm::dvec3> ground_under_cursor() const;
  sv::ViewFrame make_frame();
  void log_camera(int frame, const sv::ViewFrame& f, int width, int height);
  void save_screenshot(const std::string& path, sv::ViewFrame frame, int scale);
  void note(const std::string& text);
  void build_trails();
  void window_shot(const std::string& path, int width, int height);

  ViewerOptions o_;
  ViewScript script_;  // read before the window opens
  terrain::HeightField field_;
  sky::Observer place_;
  std::optional<shade::TrackedAircraft> aircraft_;
  GlfwWindow window_;
  gpu::GpuRenderer renderer_;
  sv::LightingReuse lighting_reuse_{sv::kSunTolerance, sv::kSkyTolerance};
  shading::ProductOptions options_;
  std::unique_ptr<sv::SceneView> scene_;
  double exaggeration_;
  sv::CameraRig rig_;
  CameraAim aim_{field_};
  std::optional<sv::Timeline> timeline_;
  InputState input_;
  PanelState panel_;
  PanelInfo info_;
  std::size_t followed_ = 0;
  int quality_ = 1;
  double frame_s_ = 0.0;  // the fixed step of scripted runs, else 0
  bool quit_ = false, screenshot_now_ = false;
  std::ofstream camera_log_;
  sv::ViewFrame last_frame_;
  std::optional<terrain::BrushStroke> stroke_;  // while the left button is down
  sv::ViewTimings sum_;  // of the frames after the first
  double wall_sum_ms_ = 0.0;
  int summed_ = 0;
  std::unique_ptr<sv::TrailDraw> trails_;
  int trail_colour_ = -1;  // of trails_
};

Viewer::Viewer(const ViewerOptions& o)
    : o_(checked(o)),
      script_(o.script.empty() ? ViewScript() : ViewScript::read(o.script)),
      field_(load_dems_or_scene(o.inputs, o.synthetic, o.scene_size, o.seed, o.quiet ? nullptr : &std::cerr,
                                "skylit-view")),
      window_(o.width, o.height, "skylit", o.script.empty() && o.frames == 0),
      renderer_(std::make_unique<gpu::HeadlessContext>(gpu::AdoptCurrentContext{"GLFW window"})),
      exaggeration_(o.exaggeration),
      rig_(ground()) {
  const std::optional<shading::Quality> q = shading::parse_quality(o.quality);
  const std::optional<sv::CameraMode> mode = sv::parse_camera_mode(o.camera);
  frame_s_ = (!o.script.empty() || o.frames > 0) ? 1.0 / o.fps : 0.0;
  place_ = sun_place(o.light.request, field_);

  shading::apply_quality(*q, options_);
  options_.shaded.tone = tone_curve(o.light);
  fit_to_gpu();
  if (o.refresh_frames > 0) renderer_.set_refresh_budget((field_.size() + o.refresh_frames - 1) / o.refresh_frames);
  load_aircraft();
  if (!aircraft_)
    rig_ = sv::CameraRig(ground(), sv::overview_rig_options(field_, static_cast<double>(o.width) / o.height, exaggeration_));
  double t0 = 0.0;
  if (const auto day = date_daylight(o.light.request.time, place_, o.quiet ? nullptr : &std::cerr))
    t0 = 0.5 * (day->first + day->second);  // a date alone: midway through its daylight (its solar noon)
  else if (!o.light.request.time.empty())
    t0 = sky::parse_utc_time(o.light.request.time).unix_seconds;
  if (aircraft_) {
    timeline_.emplace(aircraft_->start(), aircraft_->end());
    if (!o.light.request.time.empty()) timeline_->scrub(t0);
    timeline_->set_playing(true);
  } else {
    if (o.light.request.time.empty())
      throw std::invalid_argument("give --time for the sun, or a --track whose clock sets it");
    const auto [start, end] = local_day(t0, place_.longitude_deg);
    timeline_.emplace(start, end);
    timeline_->scrub(t0);
    timeline_->set_playing(o.frames > 0);
  }
  int speed = 0;
  while (speed + 1 < static_cast<int>(sv::kPlaybackSpeeds.size()) && sv::kPlaybackSpeeds[speed] < o.speed) ++speed;
  timeline_->set_speed_index(speed);

  scene_ = std::make_unique<sv::SceneView>(renderer_, field_, options_, aircraft_.has_value());
  rig_.set_mode(*mode);
  panel_.camera = static_cast<int>(*mode);
  panel_.quality = quality_ = static_cast<int>(*q);
  panel_.exaggeration = static_cast<float>(o.exaggeration);
  panel_.mesh_error_px = static_cast<float>(o.mesh_error_px);
  panel_.turbidity = static_cast<float>(o.light.request.turbidity);
  panel_.sky = std::max(0, index_of(kSkyChoices, o.light.request.sky));
  panel_.screenshot_scale = o.screenshot_scale;
  info_.renderer = renderer_.description();
  if (!o.camera_log.empty()) {
    camera_log_.open(o.camera_log);
    if (!camera_log_) throw std::invalid_argument("--camera-log '" + o.camera_log + "' cannot be written");
    camera_log_ << "frame,time_s,eye_x,eye_y,eye_z,width,height,shading_ms,horizons_computed,stale_texels,sun_swept";
    for (int k = 0; k < 16; ++k) camera_log_ << ",vp" << k;
    camera_log_ << "\n";
  }
}

void Viewer::note(const std::string& text) {
  if (!o_.quiet) std::cerr << "skylit-view: note: " << text << "\n";
  info_.note = text;
}

// A field over what one GPU frame takes is halved until it fits (a coarser level).
void Viewer::fit_to_gpu() {
  int halvings = 0;
  while (!renderer_.fits_field(field_.width, field_.height, shading::Product::Shaded, options_) && field_.width > 2 &&
         field_.height > 2) {
    field_ = terrain::coarsen_by_two(field_);
    ++halvings;
  }
  if (halvings > 0)
    note("the DEM is too large for one GPU frame: shown at 1/" + std::to_string(1 << halvings) + " resolution (" +
         std::to_string(field_.width) + "x" + std::to_string(field_.height) + ")");
}

void Viewer::load_aircraft() {
  if (o_.tracks.empty()) return;
  try {
    aircraft_.emplace(o_.tracks, o_.aircraft, parse_altitude_arg(o_.altitude), field_);
  } catch (const std::invalid_argument& e) {
    note(std::string(e.what()) + "; the viewer runs without aircraft");
    return;
  }
  info_.tracks = aircraft_->summary();
  // A track wholly outside the DEM is kept on the clock but cannot be seen.
  for (std::size_t k = 0; k < aircraft_->tracks(); ++k)
    if (!aircraft_->over_field(k))
      note("track " + std::to_string(k + 1) + " lies outside the DEM; its aircraft are not in view");
}

void Viewer::apply_actions() {
  sv::Timeline& t = *timeline_;
  const double frame_step = frame_s_ > 0 ? frame_s_ : 1.0 / 30.0;
  const double seconds = input_.is_held("shift") ? 10.0 : 1.0;
  for (const std::string& key : input_.pressed) {
    const std::optional<Action> a = action_for(key);
    if (!a) continue;
    switch (*a) {
      case Action::PlayPause: t.toggle_playing(); break;
      case Action::Faster: t.faster(); break;
      case Action::Slower: t.slower(); break;
      case Action::Reverse: t.toggle_reverse(); break;
      case Action::Loop: t.set_loop(!t.looping()); break;
      case Action::StepFrameForward: t.step_frames(1, frame_step * t.speed()); break;
      case Action::StepFrameBack: t.step_frames(-1, frame_step * t.speed()); break;
      case Action::StepSecondForward: t.step_seconds(seconds); break;
      case Action::StepSecondBack: t.step_seconds(-seconds); break;
      case Action::ToStart: t.scrub(t.start()); break;
      case Action::ToEnd: t.scrub(t.end()); break;
      case Action::CameraFollow: panel_.camera = 0; break;
      case Action::CameraOrbit: panel_.camera = 1; break;
      case Action::CameraFree: panel_.camera = 2; break;
      case Action::NextTrack:
        if (aircraft_ && aircraft_->tracks() > 0) followed_ = (followed_ + 1) % aircraft_->tracks();
        break;
      case Action::Brush: panel_.brush = (panel_.brush + 1) % static_cast<int>(std::size(kBrushChoices)); break;
      case Action::TogglePanel: panel_.visible = !panel_.visible; break;
      case Action::Help: panel_.help = !panel_.help; break;
      case Action::Screenshot: screenshot_now_ = true; break;
      case Action::Quit: quit_ = true; break;
    }
  }
}

// Settings the panel (or keys) changed since the last frame.
void Viewer::apply_panel() {
  const auto mode = static_cast<sv::CameraMode>(panel_.camera);
  if (mode != rig_.mode()) rig_.set_mode(mode);  // the clock keeps running
  exaggeration_ = panel_.exaggeration;
  if (panel_.quality != quality_) {  // new kernels and horizons
    quality_ = panel_.quality;
    shading::apply_quality(static_cast<shading::Quality>(quality_), options_);
    scene_.reset();
    scene_ = std::make_unique<sv::SceneView>(renderer_, field_, options_, aircraft_.has_value());
  }
  if (panel_.screenshot) screenshot_now_ = true;
}

// The ground point under the cursor: a ray through the pixel, marched against the
// exaggerated ground as drawn, fallen with the curvature (none when it meets no ground).
std::optional<glm::dvec3> Viewer::ground_under_cursor() const {
  int w = 0, h = 0;
  window_.framebuffer_size(w, h);
  const glm::dmat4 inv = glm::inverse(last_frame_.camera.proj * last_frame_.camera.view);
  const double nx = 2.0 * input_.cursor.x / w - 1.0, ny = 1.0 - 2.0 * input_.cursor.y / h;
  const glm::dvec4 a = inv * glm::dvec4(nx, ny, -1.0, 1.0), b = inv * glm::dvec4(nx, ny, 1.0, 1.0);
  const glm::dvec3 from = glm::dvec3(a) / a.w, to = glm::dvec3(b) / b.w;
  const sv::GroundHeight ground = sv::ground_of(field_, exaggeration_);
  const sv::CurvatureDrop drop = sv::drawn_drop(last_frame_);
  const double step = 0.5 * std::min(field_.mean_dx(), field_.dy);
  const double length = glm::distance(from, to);
  const glm::dvec3 dir = (to - from) / length;
  for (double s = 0.0; s < length; s += step) {
    const glm::dvec3 p = from + s * dir;
    if (p.z <= ground(p.x, p.y) - drop.at(p.x, p.y)) return p;
  }
  return std::nullopt;
}

// A click brushes the ground under the cursor once; dragging with the button down brushes
// every half radius along the cursor's ground path (terrain::BrushStroke: the same ridge
// at any frame rate; overlapping at R/2 the falloffs sum to 2.1× one application, with a
// ripple under 1 %). The renderer re-uploads the rows and refreshes the horizons.
void Viewer::apply_brush() {
  if (panel_.brush == 0) {
    stroke_.reset();
    return;
  }
  if (input_.brush_click) {
    terrain::Brush brush;
    brush.mode = panel_.brush == 1 ? terrain::BrushMode::Raise
                 : panel_.brush == 2 ? terrain::BrushMode::Lower
                                     : terrain::BrushMode::Smooth;
    brush.radius_m = panel_.brush_radius_m;
    brush.strength = brush.mode == terrain::BrushMode::Smooth ? std::min(1.0f, panel_.brush_strength / 100.0f)
                                                              : panel_.brush_strength;
    stroke_.emplace(brush, 0.5 * brush.radius_m);
  }
  if (stroke_) {
    if (const std::optional<glm::dvec3> p = ground_under_cursor()) stroke_->move_to(field_, p->x, p->y);
  }
  if (!input_.brush_held) stroke_.reset();
}

void Viewer::build_trails() {
  if (!aircraft_ || panel_.trail == trail_colour_) return;
  trail_colour_ = panel_.trail;
  trails_.reset();
  static_assert(std::size(kTrailChoices) == static_cast<std::size_t>(Trail::Climb) + 1, "kTrailChoices follow Trail");
  const Trail trail = static_cast<Trail>(trail_colour_);
  if (trail == Trail::Off) return;
  trails_ = make_trails(*aircraft_, trail_colour(trail));
}

// The window's back buffer with the panel (for the docs and tests of what a person sees).
void Viewer::window_shot(const std::string& path, int width, int height) {
  write_screenshot(path, {width, height, sv::read_framebuffer_rgb(0, width, height)}, o_.overwrite);
  if (!o_.quiet) std::cerr << "skylit-view: wrote " << path << " (the window, " << width << "x" << height << ")\n";
}

sv::ViewFrame Viewer::make_frame() {
  const double t = timeline_->time();
  shading::LightingRequest request = o_.light.request;
  request.time = shading::format_instant({t});
  request.sky = kSkyChoices[panel_.sky];
  request.turbidity = panel_.turbidity;
  const shading::ResolvedLighting lit = shading::resolve_lighting(request, place_);
  info_.sun_azimuth_deg = lit.sun_azimuth_deg;
  info_.sun_elevation_deg = lit.sun_elevation_deg;
  sv::ViewFrame frame;
  frame.shading.lighting = lighting_reuse_.next(request, lit.lighting);
  if (aircraft_) frame.shading.spheres = aircraft_->spheres_at(t);
  frame.style.tone = options_.shaded.tone;
  frame.style.exaggeration = exaggeration_;
  frame.style.max_error_px = panel_.mesh_error_px;
  rig_.set_target(aim_.at(aircraft_, followed_, t, exaggeration_));
  return frame;
}

void Viewer::log_camera(int k, const sv::ViewFrame& f, int width, int height) {
  if (!camera_log_) return;
  const glm::dmat4 vp = f.camera.proj * f.camera.view;
  char line[192];
  std::snprintf(line, sizeof line, "%d,%.3f,%.6f,%.6f,%.6f,%d,%d,%.3f,%d,%zu,%d", k, timeline_->time(), f.camera.eye.x,
                f.camera.eye.y, f.camera.eye.z, width, height, info_.timings.shading_ms,
                info_.timings.horizons_reused ? 0 : 1, info_.timings.stale_texels, info_.timings.sun_far_reused ? 0 : 1);
  camera_log_ << line;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) {
      std::snprintf(line, sizeof line, ",%.17g", vp[c][r]);
      camera_log_ << line;
    }
  camera_log_ << "\n";
  camera_log_.flush();
}

void Viewer::save_screenshot(const std::string& path, sv::ViewFrame frame, int scale) {
  int w = 0, h = 0;
  window_.framebuffer_size(w, h);
  write_screenshot(path, render_tiled(*scene_, frame, w, h, scale), o_.overwrite);
  if (!o_.quiet) std::cerr << "skylit-view: wrote " << path << " (" << w * scale << "x" << h * scale << ")\n";
}

int Viewer::run() {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the working folder
  ImGui_ImplGlfw_InitForOpenGL(window_.handle(), true);
  ImGui_ImplOpenGL3_Init("#version 450 core");
  struct ImGuiShutdown {
    ~ImGuiShutdown() {
      ImGui_ImplOpenGL3_Shutdown();
      ImGui_ImplGlfw_Shutdown();
      ImGui::DestroyContext();
    }
  } shutdown;

  auto last = std::chrono::steady_clock::now();
  for (int k = 0; !window_.should_close(); ++k) {
    const ImGuiIO& io = ImGui::GetIO();
    window_.poll(input_, io.WantCaptureKeyboard, io.WantCaptureMouse);
    script_.feed(k, input_);
    const auto now = std::chrono::steady_clock::now();
    const double wall = std::chrono::duration<double>(now - last).count();
    last = now;
    info_.frame_ms = wall * 1000.0;
    std::vector<std::string> shots, window_shots;
    std::optional<sv::CameraPose> pose;
    for (const ScriptEvent& e : script_.commands_at(k)) {
      if (e.verb == ScriptEvent::Verb::Scrub) timeline_->scrub(e.unix_seconds);
      if (e.verb == ScriptEvent::Verb::Screenshot) shots.push_back(e.path);
      if (e.verb == ScriptEvent::Verb::WindowShot) window_shots.push_back(e.path);
      if (e.verb == ScriptEvent::Verb::Pose) pose = script_pose(e);
      if (e.verb == ScriptEvent::Verb::Quit) quit_ = true;
    }
    apply_actions();
    apply_brush();
    const double dt = frame_s_ > 0 ? frame_s_ : std::min(wall, 0.25);
    if (k > 0) timeline_->advance(dt);

    int w = 0, h = 0;
    window_.framebuffer_size(w, h);
    if (w > 0 && h > 0) {
      sv::ViewFrame frame = make_frame();
      if (pose) {  // a scripted free camera
        panel_.camera = static_cast<int>(sv::CameraMode::Free);
        rig_.set_mode(sv::CameraMode::Free);
        rig_.set_pose(*pose);
      } else if (k == 0) {  // a cut to the camera (free mode: where the orbit settles)
        rig_.settle();
      } else {
        rig_.update(dt, camera_input(input_));
      }
      frame.camera = sv::perspective_camera(rig_.pose(), field_, w, h, exaggeration_, frame.shading.spheres);
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      info_.timings = scene_->draw(frame, w, h, true);
      if (k > 1) {  // frame 0 computes the horizons; frame 1's wall time includes it
        sum_.shading_ms += info_.timings.shading_ms;
        sum_.sky_ms += info_.timings.sky_ms;
        sum_.terrain_ms += info_.timings.terrain_ms;
        sum_.bodies_ms += info_.timings.bodies_ms;
        wall_sum_ms_ += info_.frame_ms;
        ++summed_;
      }
      last_frame_ = frame;
      log_camera(k, frame, w, h);
      build_trails();
      if (trails_) trails_->draw(frame.camera.proj * frame.camera.view, exaggeration_, sv::drawn_drop(frame), timeline_->time());

      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      draw_panel(panel_, *timeline_, info_);
      ImGui::Render();
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      for (const std::string& path : window_shots) window_shot(path, w, h);
      window_.swap();

      for (const std::string& path : shots) save_screenshot(path, frame, panel_.screenshot_scale);
      if (screenshot_now_) {
        save_screenshot(default_screenshot_name(), frame, panel_.screenshot_scale);
        screenshot_now_ = false;
      }
      if (o_.frames > 0 && k + 1 >= o_.frames) {
        save_screenshot(o_.screenshot, frame, panel_.screenshot_scale);
        break;
      }
    }
    apply_panel();
    input_.end_frame();
    if (quit_) break;
  }
  if (o_.timings && summed_ > 0)
    std::printf("per frame (mean of %d): shading %.1f ms, sky %.1f ms, terrain %.1f ms, aircraft %.1f ms, "
                "whole frame %.1f ms (%.2f fps)\n",
                summed_, sum_.shading_ms / summed_, sum_.sky_ms / summed_, sum_.terrain_ms / summed_,
                sum_.bodies_ms / summed_, wall_sum_ms_ / summed_, 1000.0 * summed_ / wall_sum_ms_);
  return 0;
}

}  // namespace

int run_viewer(const ViewerOptions& options) { return Viewer(options).run(); }

}  // namespace skylit::app::view::window
