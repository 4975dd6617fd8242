// `skylit view ARGS`: runs skylit-view (the window, beside this executable) with ARGS,
// so the headless commands never link or load GLFW and X.
#include "app/commands.h"

#include <CLI/CLI.hpp>

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace skylit::app::view {

void add_view_command(CLI::App& root, Action& run) {
  CLI::App* cmd = root.add_subcommand(
      "view", "Fly over a DEM in a window (skylit-view; `skylit view --help` lists its options)");
  cmd->set_help_flag();  // --help goes to skylit-view
  cmd->prefix_command();
  cmd->allow_extras();
  cmd->callback([&run, cmd] {
    run = [args = cmd->remaining()] {
      std::error_code ec;
      const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
      const std::filesystem::path viewer = self.parent_path() / "skylit-view";
      std::vector<std::string> argv_text{viewer.string()};
      argv_text.insert(argv_text.end(), args.begin(), args.end());
      std::vector<char*> argv;
      for (std::string& a : argv_text) argv.push_back(a.data());
      argv.push_back(nullptr);
      ::execv(viewer.c_str(), argv.data());
      throw std::runtime_error("cannot run the viewer '" + viewer.string() + "' (" + std::strerror(errno) +
                               "): build skylit-view, or use `skylit render` for frames without a window");
      return 1;
    };
  });
}

}  // namespace skylit::app::view
