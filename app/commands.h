// Subcommands of the skylit executable. Each add_*_command registers its
// options on the root app and, when selected, stores its action in `run`.
#pragma once

#include "app/common/cli_fwd.h"

#include <functional>

namespace skylit::app {

using Action = std::function<int()>;

// Runs the CLI: parses, dispatches, turns exceptions into one-line errors.
int run_cli(int argc, char** argv);

}  // namespace skylit::app

namespace skylit::app::shade {  // app/shade/: the export tool

void add_shade_command(CLI::App& root, Action& run);
void add_sun_command(CLI::App& root, Action& run);
void add_scene_command(CLI::App& root, Action& run);

}  // namespace skylit::app::shade

namespace skylit::app::bench {  // app/bench/: speed against error

void add_bench_command(CLI::App& root, Action& run);

}  // namespace skylit::app::bench

namespace skylit::app::tiles {  // app/tiles/: web-map tiles

void add_tiles_command(CLI::App& root, Action& run);

}  // namespace skylit::app::tiles

namespace skylit::app::flight {  // app/flight/: aircraft and their tracks

void add_track_command(CLI::App& root, Action& run);
void add_spheres_fit_command(CLI::App& root, Action& run);

}  // namespace skylit::app::flight

namespace skylit::app::view {  // app/view/: the viewer's frames

void add_render_command(CLI::App& root, Action& run);
void add_view_command(CLI::App& root, Action& run);  // runs skylit-view

}  // namespace skylit::app::view
