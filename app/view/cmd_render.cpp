// `skylit render`: the viewer's frames without a window (headless EGL): a camera that
// follows, orbits or looks straight down over the DEM, at a fixed time step through a
// flight track (or a time with no track), each frame lit by the sun and sky of its time
// with the aircraft's soft shadows, to numbered PNGs or a video (frame_sink.h).
#include "app/commands.h"
#include "app/common/altitude_arg.h"
#include "app/common/date_daylight.h"
#include "app/common/lighting_args.h"
#include "app/common/progress.h"
#include "app/common/synthetic_scene.h"
#include "app/shade/tracked_aircraft.h"
#include "app/view/aircraft_trails.h"
#include "app/view/mesh_error.h"
#include "app/view/camera_aim.h"
#include "app/view/frame_sink.h"
#include "gpu/gpu_renderer.h"
#include "shading/sky/time_utc.h"
#include "shading/time_series.h"
#include "view/camera.h"
#include "view/offscreen_target.h"
#include "view/scene_view.h"
#include "view/lighting_reuse.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace skylit::app::view {
namespace {

namespace sv = skylit::view;

// The orbit camera circles its target once a minute of video.
constexpr double kOrbitRateRadPerS = 2.0 * 3.14159265358979323846 / 60.0;
// Most frames one render writes: ~9 hours of video at 30 fps, beyond any flight replay.
constexpr int kMaxFrames = 1'000'000;
// A date alone (--time 2026-06-21) without --speed: the day, sunrise to sunset, in this
// much video.
constexpr double kDayVideoSeconds = 30.0;

struct RenderArgs {
  std::vector<std::string> inputs;
  bool synthetic = false;
  int scene_size = 512;
  std::uint64_t seed = 1;
  std::string output;
  std::string camera = "follow";
  std::string size = "1280x720";
  double fps = 30.0;
  std::optional<double> duration;  // track seconds
  std::string from, to;
  std::optional<double> speed;  // track seconds per video second (default: 1, a day in kDayVideoSeconds)
  std::vector<std::string> tracks;
  std::string aircraft = "glider", altitude = "gnss";
  std::string trail = "altitude";  // aircraft_trails.h
  double exaggeration = 1.0;
  double mesh_error_px = skylit::view::kDefaultMeshErrorPx;
  bool overwrite = false, quiet = false, timings = false;
  LightingArgs light;
};

std::pair<int, int> parse_size(const std::string& text) {
  int w = 0, h = 0;
  char x = 0, rest = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &rest) != 3 || (x != 'x' && x != 'X') || w < 1 || h < 1)
    throw std::invalid_argument("--size '" + text + "' is not WIDTHxHEIGHT (e.g. 1280x720)");
  return {w, h};
}

double parse_time(const std::string& text, const char* flag) {
  try {
    return sky::parse_utc_time(text).unix_seconds;
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string(flag) + " '" + text + "': " + e.what());
  }
}

int run_render(const RenderArgs& a) {
  const auto [width, height] = parse_size(a.size);
  const bool nadir = a.camera == "ortho-nadir";
  const std::optional<sv::CameraMode> mode = sv::parse_camera_mode(a.camera);
  if (!nadir && !mode) throw std::invalid_argument("--camera '" + a.camera + "' is not follow, orbit, free or ortho-nadir");
  if (!(a.exaggeration > 0.0) || a.exaggeration > 100.0) throw std::invalid_argument("--exaggeration must be in (0, 100]");
  check_mesh_error(a.mesh_error_px);
  const auto trail = parse_trail(a.trail);
  if (!trail) throw std::invalid_argument("--trail '" + a.trail + "' is not altitude, climb or off");
  const terrain::HeightField field =
      load_dems_or_scene(a.inputs, a.synthetic, a.scene_size, a.seed, a.quiet ? nullptr : &std::cerr, "skylit");

  std::optional<shade::TrackedAircraft> aircraft;
  if (!a.tracks.empty()) aircraft.emplace(a.tracks, a.aircraft, parse_altitude_arg(a.altitude), field);
  // A track wholly beside the DEM still sets the clock; its aircraft are not in the frames.
  for (std::size_t k = 0; aircraft && !a.quiet && k < aircraft->tracks(); ++k)
    if (!aircraft->over_field(k))
      std::cerr << "skylit: note: track " << k + 1 << " lies outside the DEM; its aircraft are not in the frames\n";
  const sky::Observer place = sun_place(a.light.request, field);
  // The span of track time the frames cover; a date alone is that local day's daylight.
  const std::optional<std::pair<double, double>> day =
      a.from.empty() ? date_daylight(a.light.request.time, place, a.quiet ? nullptr : &std::cerr) : std::nullopt;
  double t0 = 0.0;
  if (!a.from.empty()) t0 = parse_time(a.from, "--from");
  else if (day) t0 = day->first;
  else if (!a.light.request.time.empty()) t0 = parse_time(a.light.request.time, "--time");
  else if (aircraft) t0 = aircraft->start();
  else throw std::invalid_argument("give --time (or --from) for the sun, or a --track whose start sets it");
  double t1 = t0;
  if (!a.to.empty()) t1 = parse_time(a.to, "--to");
  else if (a.duration) t1 = t0 + *a.duration;
  else if (day) t1 = day->second;
  else if (aircraft) t1 = aircraft->end();
  if (!(t1 >= t0)) throw std::invalid_argument("the frames' end is before their start (--from/--to/--duration)");
  const double speed = a.speed ? *a.speed : day ? std::max(1.0, (t1 - t0) / kDayVideoSeconds) : 1.0;
  if (!(speed > 0.0) || !std::isfinite(speed)) throw std::invalid_argument("--speed must be > 0");
  if (a.light.request.sun_azimuth_deg || a.light.request.sun_elevation_deg)
    throw std::invalid_argument("render moves the sun with the clock: give --time, not --sun-azimuth/--sun-elevation");
  // Before the frames are counted (the sink checks it too, after).
  if (!(a.fps > 0.0) || a.fps > kMaxFrameRate)
    throw std::invalid_argument("--fps must be in (0, " + std::to_string(static_cast<int>(kMaxFrameRate)) +
                                "] frames per second");
  const double frame_count = 1.0 + std::floor((t1 - t0) / speed * a.fps + 1e-9);
  if (frame_count > kMaxFrames)
    throw std::invalid_argument(std::to_string(static_cast<long long>(frame_count)) + " frames (" +
                                std::to_string(std::lround(t1 - t0)) + " s of track time at --speed and --fps) are over " +
                                std::to_string(kMaxFrames) + ": raise --speed or lower --fps");
  const int frames = static_cast<int>(frame_count);

  SinkOptions so;
  so.width = width;
  so.height = height;
  so.fps = a.fps;
  so.overwrite = a.overwrite;
  so.frames = frames;
  std::unique_ptr<FrameSink> sink = open_frame_sink(a.output, so);

  gpu::GpuRenderer renderer;
  shading::ProductOptions options;
  options.shaded.tone = tone_curve(a.light);
  sv::SceneView scene(renderer, field, options, aircraft.has_value());
  sv::LightingReuse lighting_reuse(sv::kSunTolerance, sv::kSkyTolerance);
  sv::OffscreenTarget target(width, height);
  // The straight-down frame is the export's picture: no trail over it.
  const std::unique_ptr<sv::TrailDraw> trails =
      aircraft && *trail != Trail::Off && !nadir ? make_trails(*aircraft, trail_colour(*trail)) : nullptr;
  sv::CameraRig rig(sv::ground_of(field, a.exaggeration), aircraft ? sv::RigOptions{}
                             : sv::overview_rig_options(field, static_cast<double>(width) / height, a.exaggeration));
  CameraAim aim(field);
  if (mode) rig.set_mode(*mode);
  if (!a.quiet)
    std::cerr << "skylit: " << frames << " frames " << width << "x" << height << " from "
              << sky::format_utc_time({t0}) << " to " << sky::format_utc_time({t1}) << " on "
              << renderer.description() << (aircraft ? ", " + aircraft->summary() : std::string()) << " -> "
              << sink->description() << "\n";
  sv::ViewTimings sum, first;
  std::vector<double> later_draw_ms;  // frames 2.. (the median: a re-sweep of the sun is an outlier)
  double read_sum_ms = 0.0;
  ProgressBar progress("render", a.quiet);
  for (int k = 0; k < frames; ++k) {
    const double t = t0 + k * speed / a.fps;
    shading::LightingRequest request = a.light.request;
    request.time = shading::format_instant({t});
    sv::ViewFrame frame;
    frame.shading.lighting = lighting_reuse.next(request, shading::resolve_lighting(request, place).lighting);
    if (aircraft) frame.shading.spheres = aircraft->spheres_at(t);
    frame.style.tone = options.shaded.tone;
    frame.style.exaggeration = a.exaggeration;
    frame.style.max_error_px = a.mesh_error_px;
    if (nadir) {
      frame.camera = sv::ortho_nadir_camera(field, a.exaggeration);
      frame.draw_bodies = false;
    } else {
      rig.set_target(aim.at(aircraft, 0, t, a.exaggeration));
      sv::CameraInput turn;
      if (mode == sv::CameraMode::Orbit) turn.yaw_rad = kOrbitRateRadPerS / a.fps;  // per video second
      if (k == 0) rig.settle();
      else rig.update(1.0 / a.fps, turn);
      frame.camera = sv::perspective_camera(rig.pose(), field, width, height, a.exaggeration, frame.shading.spheres);

    }
    target.bind();
    const sv::ViewTimings pass = scene.draw(frame, width, height, a.timings);
    if (trails) trails->draw(frame.camera.proj * frame.camera.view, a.exaggeration, sv::drawn_drop(frame), t);
    const auto read_start = std::chrono::steady_clock::now();
    const std::vector<std::uint8_t> rgb = target.read_rgb();
    const double read_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - read_start).count();
    if (a.timings)
      std::printf("frame %d: shading %.1f ms (%s), sky %.1f ms, terrain %.1f ms (%zu patches), "
                  "aircraft %.1f ms, read-back %.1f ms\n",
                  k, pass.shading_ms,
                  pass.shading_kept     ? "lighting kept: the aircraft's texels only"
                  : pass.sun_far_reused ? "sun's far horizon kept"
                                        : "sun's far horizon swept",
                  pass.sky_ms, pass.terrain_ms,
                  pass.terrain_nodes, pass.bodies_ms, read_ms);
    if (k > 0) {  // the first frame computes the horizons
      sum.shading_ms += pass.shading_ms;
      sum.sky_ms += pass.sky_ms;
      sum.terrain_ms += pass.terrain_ms;
      sum.bodies_ms += pass.bodies_ms;
      sum.total_ms += pass.total_ms;
      later_draw_ms.push_back(pass.total_ms);
      read_sum_ms += read_ms;
    } else {
      first = pass;
    }
    sink->write(rgb);
    progress.update(static_cast<double>(k + 1) / frames);
  }
  sink->finish();
  progress.finish();
  if (!a.quiet) std::cerr << "skylit: wrote " << sink->description() << "\n";
  if (a.timings) {
    std::printf("first frame: %.1f ms (shading %.1f ms, horizons computed)\n", first.total_ms, first.shading_ms);
    if (frames > 1) {
      const double n = frames - 1;
      std::printf("per frame (mean of %d): shading %.1f ms, sky %.1f ms, terrain %.1f ms, aircraft %.1f ms, "
                  "draw %.1f ms, read-back %.1f ms\n",
                  frames - 1, sum.shading_ms / n, sum.sky_ms / n, sum.terrain_ms / n, sum.bodies_ms / n,
                  sum.total_ms / n, read_sum_ms / n);
      std::nth_element(later_draw_ms.begin(), later_draw_ms.begin() + later_draw_ms.size() / 2, later_draw_ms.end());
      std::printf("median draw of frames 2..: %.1f ms\n", later_draw_ms[later_draw_ms.size() / 2]);
    }
  }
  return 0;
}

}  // namespace

void add_render_command(CLI::App& root, Action& run) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = root.add_subcommand("render", "Render the viewer's frames headless (no display): PNG frames or a video");
  cmd->add_option("INPUT", args->inputs, "DEM file(s)");
  cmd->add_option("-o,--output", args->output, "frames_%05d.png, or a video: .mp4/.mkv/.mov (H.264), .webm (VP9)")->required();
  cmd->add_flag("--synthetic", args->synthetic, "Use the built-in synthetic scene instead of INPUT");
  cmd->add_option("--scene-size", args->scene_size, "Width and height of the synthetic scene (texels)")->capture_default_str();
  cmd->add_option("--seed", args->seed, "Seed of the synthetic scene")->capture_default_str();
  cmd->add_option("--camera", args->camera, "follow | orbit | free | ortho-nadir (straight down over the DEM)")->capture_default_str();
  cmd->add_option("--size", args->size, "Frame size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--fps", args->fps, "Frames per video second")->capture_default_str();
  cmd->add_option("--duration", args->duration, "Seconds of track time (default: the whole track)");
  cmd->add_option("--from", args->from, "First frame's time (ISO 8601 with a zone; default: the track's start)");
  cmd->add_option("--to", args->to, "Last frame's time");
  cmd->add_option("--speed", args->speed,
                  "Track seconds per video second (default 1; with a date alone, its daylight in 30 s of video)");
  cmd->add_option("--track", args->tracks,
                  "Flight track(s) (IGC, GPX, KML gx:Track, CSV; repeat for several): their aircraft and shadows");
  cmd->add_option("--aircraft", args->aircraft, "The sphere set of --track's aircraft (as shade)")->capture_default_str();
  cmd->add_option("--track-altitude", args->altitude, "--track's altitude: gnss | pressure | agl-offset=M")->capture_default_str();
  cmd->add_option("--trail", args->trail, "The tracks' trails up to each frame's time: altitude | climb | off")
      ->capture_default_str();
  cmd->add_option("--exaggeration", args->exaggeration, "Vertical exaggeration of the drawn terrain")->capture_default_str();
  cmd->add_option("--mesh-error", args->mesh_error_px,
                  "The terrain mesh's error on screen in pixels (0.5 to 16): more is faster, coarser at ridges")
      ->capture_default_str();
  cmd->add_flag("--overwrite", args->overwrite, "Replace an existing output");
  cmd->add_flag("-q,--quiet", args->quiet, "No progress or notes");
  cmd->add_flag("--timings", args->timings, "Finish each pass before the next and print the mean time per pass");
  args->light.request.sky = "preetham";  // a picture: the sky behind the terrain is seen
  add_lighting_options(*cmd, args->light,
                       "The time of the first frame without --track (the clock then runs at --speed), or a date "
                       "alone (2026-06-21): that local day from sunrise to sunset at the DEM");
  cmd->callback([&run, args] { run = [args] { return run_render(*args); }; });
}

}  // namespace skylit::app::view
