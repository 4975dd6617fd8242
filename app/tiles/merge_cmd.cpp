#include "app/tiles/merge_cmd.h"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "tiles/merge.h"

namespace skylit::app::tiles {
namespace {

struct MergeArgs {
  std::vector<std::string> inputs;
  std::string output;
  bool overwrite = false, tms = false, quiet = false;
};

int run_merge(const MergeArgs& a) {
  namespace st = skylit::tiles;
  if (a.inputs.empty()) throw std::invalid_argument("tiles merge: no input archives given");
  if (a.output.empty()) throw std::invalid_argument("tiles merge: no output given (-o)");
  std::error_code ec;
  if (!a.overwrite && std::filesystem::exists(a.output, ec))
    throw std::invalid_argument("output '" + a.output + "' exists: pass --overwrite to replace it");
  st::ArchiveOptions o;
  o.mode = a.overwrite ? st::OpenMode::Overwrite : st::OpenMode::Create;
  o.scheme = a.tms ? st::Scheme::Tms : st::Scheme::Xyz;
  st::merge(a.inputs, a.output, o);
  if (!a.quiet) std::cerr << "skylit: merged " << a.inputs.size() << " archives into " << a.output << "\n";
  return 0;
}

}  // namespace

CLI::App* add_merge_subcommand(CLI::App& tiles, Action& run) {
  auto a = std::make_shared<MergeArgs>();
  auto* cmd = tiles.add_subcommand("merge", "Merge tile archives (e.g. the shards of one run) into OUT");
  cmd->add_option("ARCHIVE", a->inputs, "Input archives: .mbtiles, .pmtiles or folders")->required();
  cmd->add_option("-o,--output", a->output, "Output archive (its kind from the path)")->required();
  cmd->add_flag("--overwrite", a->overwrite, "Replace OUT if it exists");
  cmd->add_flag("--tms", a->tms, "Folder output rows in TMS order");
  cmd->add_flag("-q,--quiet", a->quiet, "No summary line");
  cmd->callback([&run, a] { run = [a] { return run_merge(*a); }; });
  return cmd;
}

}  // namespace skylit::app::tiles
