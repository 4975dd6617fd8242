#include "app/commands.h"

#include <exception>
#include <iostream>

namespace skylit::app {

int run_cli(int argc, char** argv) {
  CLI::App root{"skylit: sky-lit soft shadows for terrain (DEMs), skies and aircraft"};
  root.set_version_flag("--version", std::string("skylit ") + SKYLIT_VERSION);
  root.require_subcommand(1);
  Action run;
  add_shade_command(root, run);
  try {
    root.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return root.exit(e);
  }
  try {
    return run ? run() : 0;
  } catch (const std::exception& e) {
    std::cerr << "skylit: error: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace skylit::app
