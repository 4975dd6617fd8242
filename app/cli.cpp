#include "app/commands.h"
#include "app/common/gdal_style_args.h"
#include "app/common/option_flags.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <exception>
#include <iostream>

namespace skylit::app {

int run_cli(int argc, char** argv) {
  CLI::App root{"skylit: sky-lit soft shadows for terrain (DEMs), skies and aircraft"};
  root.set_version_flag("--version", std::string("skylit ") + SKYLIT_VERSION);
  root.require_subcommand(1);
  Action run;
  shade::add_shade_command(root, run);
  shade::add_sun_command(root, run);
  bench::add_bench_command(root, run);
  shade::add_scene_command(root, run);
  flight::add_spheres_fit_command(root, run);
  flight::add_track_command(root, run);
  tiles::add_tiles_command(root, run);
  view::add_render_command(root, run);
  view::add_view_command(root, run);
  try {
    // CLI11 wants argv in reverse order when given as a vector.
    std::vector<std::string> args = normalise_gdal_style_args(argc, argv);
    args.erase(args.begin());
    std::reverse(args.begin(), args.end());
    root.parse(args);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return root.exit(e);  // --help, --version
    std::cerr << "skylit: error: " << e.what() << " (see --help)\n";
    return 2;
  }
  try {
    return run ? run() : 0;
  } catch (const std::exception& e) {
    std::cerr << "skylit: error: " << message_with_flags(e) << "\n";
    return 1;
  }
}

}  // namespace skylit::app
