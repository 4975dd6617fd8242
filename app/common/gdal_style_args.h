// gdaldem-style single-dash long flags (-of, -co, -compute_edges, ...) mapped to
// the double-dash spelling CLI11 parses, so both spellings work.
#pragma once

#include <string>
#include <vector>

namespace skylit::app {

std::vector<std::string> normalise_gdal_style_args(int argc, char** argv);

}  // namespace skylit::app
