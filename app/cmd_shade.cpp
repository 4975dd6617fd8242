#include "app/commands.h"

#include <stdexcept>

namespace skylit::app {

// TEMPORARY skeleton: replaced by the shade tool (issue 3).
void add_shade_command(CLI::App& root, Action& run) {
  auto* cmd = root.add_subcommand("shade", "Shade a DEM: horizon, svf, skyview, shaded products");
  cmd->callback([&run] { run = [] { throw std::runtime_error("shade: not built yet"); return 1; }; });
}

}  // namespace skylit::app
