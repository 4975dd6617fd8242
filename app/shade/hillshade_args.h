// gdaldem hillshade's own flags of `skylit shade -p hillshade` (-alg, -combined,
// -multidirectional, -igor), turned into the relief library's options.
#pragma once

#include "shading/relief/gdal_hillshade.h"

#include "app/common/cli_fwd.h"

#include <optional>
#include <string>

namespace skylit::app::shade {

struct HillshadeArgs {
  std::string alg = "Horn";
  bool combined = false, multidirectional = false, igor = false;
};

void add_hillshade_options(CLI::App& cmd, HillshadeArgs& args);

// gdaldem's defaults where a value is not given: azimuth 315, altitude 45. Throws
// std::invalid_argument for two variants at once.
relief::HillshadeOptions hillshade_options(const HillshadeArgs& args, double z, std::optional<double> azimuth_deg,
                                           std::optional<double> altitude_deg, bool compute_edges);

}  // namespace skylit::app::shade
