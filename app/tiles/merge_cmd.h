// `skylit tiles merge A B ... -o OUT`: shard archives (of any kinds) into one.
#pragma once

#include "app/common/cli_fwd.h"

#include "app/commands.h"

namespace skylit::app::tiles {

// Registers `merge` under the tiles command; returns it so the parent can tell which ran.
CLI::App* add_merge_subcommand(CLI::App& tiles, Action& run);

}  // namespace skylit::app::tiles
