// `skylit shade -p color-relief`: the DEM's heights through a colour table, as
// `gdaldem color-relief` writes them (Byte R, G, B[, A] GeoTIFF, same georeferencing).
#pragma once

#include "shading/relief/color_relief.h"

#include <string>

namespace skylit::app::shade {

struct ColorReliefArgs {
  std::string input;
  std::string color_file;
  std::string output;
  bool alpha = false;
  bool overwrite = false;
  relief::ColorSelection selection = relief::ColorSelection::Interpolate;
};

// A file path as given, else a shipped ramp (data/ramps/NAME.txt of the source tree);
// throws std::invalid_argument listing the ramp names.
std::string resolve_color_file(const std::string& name);

// Throws std::invalid_argument / std::runtime_error; leaves no output file on failure.
int run_color_relief(const ColorReliefArgs& args);

}  // namespace skylit::app::shade
