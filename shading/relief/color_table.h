// Colour tables in gdaldem color-relief syntax (GDAL 3.6 apps/gdaldem_lib.cpp, matched
// empirically against Debian's gdaldem 3.6):
//  * one entry a line: `elevation R G B [A]` or `elevation NAME [A]` (white, black, red,
//    green, blue, yellow, magenta, cyan, aqua, grey, gray, orange, brown, purple, violet,
//    indigo), fields separated by any run of spaces, tabs, commas or colons;
//  * elevation `nv` is the source's nodata value (0 when the source has none, as gdaldem's
//    atof reads it), `P%` is min + P/100·(max − min) of the valid heights, 0 ≤ P ≤ 100;
//  * lines whose first field starts with '#' or '/' are comments, blank lines are skipped;
//  * a `# COLOR_MODEL = RGB` line makes it a GMT .cpt: `z0 R G B z1 R G B` slices give two
//    entries, `N R G B` the nodata colour, B and F lines and other lines are ignored.
// Stricter than gdaldem: a line it would read with atoi as 0 (non-numeric fields) or skip
// silently (one field) is an error naming the file and the line.
#pragma once

#include <functional>
#include <istream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace skylit::relief {

struct ColorEntry {
  double value = 0.0;
  int r = 0, g = 0, b = 0, a = 255;
};

// What the table's elevations may refer to: the source's nodata value and, for
// percentages, its (min, max) over valid heights (asked for only when a percentage occurs).
struct SourceInfo {
  std::optional<double> nodata;
  std::function<std::pair<double, double>()> min_max;
};

// Entries sorted by value as gdaldem orders and spreads them (see color_table.cpp).
struct ColorTable {
  std::vector<ColorEntry> entries;
};

// Parses `in`; `name` names it in errors ("NAME:LINE: why"). Throws std::invalid_argument
// for a bad line or a table without entries.
ColorTable parse_color_table(std::istream& in, const std::string& name, const SourceInfo& source);
// Opens and parses `path`; throws std::invalid_argument when it cannot be read.
ColorTable read_color_table(const std::string& path, const SourceInfo& source);

}  // namespace skylit::relief
