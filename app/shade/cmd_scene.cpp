// `skylit scene`: writes the built-in synthetic scene (the one `shade --synthetic`
// shades) as a Float32 GeoTIFF, so other tools — gdaldem in the CLI benchmark, GIS
// viewers — can read exactly the heights skylit shades.
#include "app/commands.h"
#include "app/common/synthetic_scene.h"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>

#include "terrain/raster_writer.h"

namespace skylit::app::shade {
namespace {

struct SceneArgs {
  std::string output;
  int size = 512;
  unsigned seed = 1;
  bool overwrite = false;
  bool quiet = false;
};

int run_scene(const SceneArgs& a) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(a.output, ec) && !a.overwrite)
    throw std::invalid_argument("output '" + a.output + "' exists; pass --overwrite to replace it");
  const terrain::HeightField field = make_georeferenced_scene(a.size, a.seed);
  terrain::RasterWriteOptions w;
  w.overwrite = a.overwrite;
  terrain::write_height_field(a.output, field, w);
  if (!a.quiet) std::cerr << "skylit: wrote " << a.output << " (" << field.width << "x" << field.height << ", seed " << a.seed << ")\n";
  return 0;
}

}  // namespace

void add_scene_command(CLI::App& root, Action& run) {
  auto args = std::make_shared<SceneArgs>();
  CLI::App* cmd = root.add_subcommand("scene", "Write the built-in synthetic scene (as shade --synthetic) as a GeoTIFF DEM");
  cmd->add_option("-o,--output", args->output, "Output GeoTIFF")->required();
  cmd->add_option("--size", args->size, "Width and height (pixels)")->check(CLI::Range(2, 16384))->capture_default_str();
  cmd->add_option("--seed", args->seed, "Seed")->capture_default_str();
  cmd->add_flag("--overwrite", args->overwrite, "Replace OUTPUT if it exists");
  cmd->add_flag("-q,--quiet", args->quiet, "No messages");
  cmd->callback([&run, args] { run = [args] { return run_scene(*args); }; });
}

}  // namespace skylit::app::shade
