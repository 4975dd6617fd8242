// skylit-view: the fly-through viewer's window (GLFW, X11), an executable of its own so
// that the headless `skylit` never loads X libraries; `skylit view ARGS` runs it.
#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>

#include "app/common/option_flags.h"
#include "app/view/window/viewer.h"

int main(int argc, char** argv) {
  using skylit::app::view::window::ViewerOptions;
  ViewerOptions o;
  o.light.request.sky = "preetham";
  CLI::App app{"skylit view: fly over a DEM lit by the sun and sky of the clock, with flight tracks and their "
               "aircraft's soft shadows (F1 in the window lists the keys)"};
  app.set_version_flag("--version", std::string("skylit-view ") + SKYLIT_VERSION);
  app.add_option("INPUT", o.inputs, "DEM file(s)");
  app.add_flag("--synthetic", o.synthetic, "Use the built-in synthetic scene instead of INPUT");
  app.add_option("--scene-size", o.scene_size, "Width and height of the synthetic scene (texels)")->capture_default_str();
  app.add_option("--seed", o.seed, "Seed of the synthetic scene")->capture_default_str();
  app.add_option("--track", o.tracks, "Flight track(s) (IGC, GPX, KML gx:Track, CSV); repeat for several");
  app.add_option("--aircraft", o.aircraft, "The tracks' sphere set (as shade)")->capture_default_str();
  app.add_option("--track-altitude", o.altitude, "gnss | pressure | agl-offset=M")->capture_default_str();
  app.add_option("--quality", o.quality, "fast | default | high")->capture_default_str();
  app.add_option("--exaggeration", o.exaggeration, "Vertical exaggeration")->capture_default_str();
  app.add_option("--mesh-error", o.mesh_error_px,
                 "The terrain mesh's error on screen in pixels (0.5 to 16; the panel's \"mesh error\"): more is faster")
      ->capture_default_str();
  app.add_option("--refresh-frames", o.refresh_frames,
                 "After a brush edit: shade the edited area at once and the rest of the field over this many frames (0: at once)")
      ->capture_default_str();
  app.add_option("--camera", o.camera, "follow | orbit | free")->capture_default_str();
  app.add_option("--width", o.width, "Window width")->capture_default_str();
  app.add_option("--height", o.height, "Window height")->capture_default_str();
  app.add_option("--speed", o.speed, "Track seconds per second (0.25 to 256)")->capture_default_str();
  app.add_option("--script", o.script, "Input events by frame (app/view/window/view_script.h); fixed 1/--fps steps");
  app.add_option("--screenshot", o.screenshot, "With --frames: the last frame's PNG");
  app.add_option("--frames", o.frames, "Play this many frames at 1/--fps steps, save --screenshot and exit");
  app.add_option("--fps", o.fps, "Frames per second of scripted runs")->capture_default_str();
  app.add_option("--screenshot-scale", o.screenshot_scale, "Screenshots at this many times the window (tiled)")
      ->capture_default_str();
  app.add_option("--camera-log", o.camera_log, "CSV of each frame's clock, eye and view-projection (tests)");
  app.add_flag("--overwrite", o.overwrite, "Replace existing screenshots");
  app.add_flag("-q,--quiet", o.quiet, "No notes");
  app.add_flag("--timings", o.timings, "Print the mean time per pass of the frames after the first at exit");
  skylit::app::add_lighting_options(
      app, o.light, "The clock's start (with --track: a time within it), or a date alone (2026-06-21): its solar noon");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "skylit-view: error: " << e.what() << " (see --help)\n";
    return 2;
  }
  try {
    return skylit::app::view::window::run_viewer(o);
  } catch (const std::exception& e) {
    std::cerr << "skylit-view: error: " << skylit::app::message_with_flags(e) << "\n";
    return 1;
  }
}
