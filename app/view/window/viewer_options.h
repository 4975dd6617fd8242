// What `skylit-view` (and `skylit view`) is asked to show, from its command line.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/common/lighting_args.h"
#include "view/terrain_lod.h"

namespace skylit::app::view::window {

struct ViewerOptions {
  std::vector<std::string> inputs;
  bool synthetic = false;
  int scene_size = 512;
  std::uint64_t seed = 1;
  std::vector<std::string> tracks;
  std::string aircraft = "glider", altitude = "gnss";
  LightingArgs light;  // --time: the clock's start (with a track: a time in it)
  std::string quality = "default";
  double exaggeration = 1.0;
  double mesh_error_px = skylit::view::kDefaultMeshErrorPx;
  // After a brush edit: the edited area is shaded at once and the rest of the field over
  // this many frames (0: all of it in the edit's frame).
  int refresh_frames = 32;
  std::string camera = "follow";
  int width = 1280, height = 720;
  double speed = 1.0;  // track seconds per wall second
  // Scripted runs step a fixed 1/fps of wall time per frame (deterministic frames).
  std::string script;
  std::string screenshot;  // with frames: the last frame's file
  int frames = 0;          // > 0: play this many frames, save --screenshot, exit
  double fps = 30.0;
  int screenshot_scale = 1;
  std::string camera_log;  // CSV: each frame's clock, eye and view-projection
  bool overwrite = false;
  bool quiet = false;
  bool timings = false;  // print the mean time per pass at exit
};

}  // namespace skylit::app::view::window
