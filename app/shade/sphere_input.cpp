#include "app/shade/sphere_input.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace skylit::app::shade {
namespace {

std::string trimmed_lower(std::string s) {
  s.erase(std::remove_if(s.begin(), s.end(), [](unsigned char c) { return std::isspace(c); }), s.end());
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

}  // namespace

std::vector<blockers::Sphere> read_spheres_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument("--spheres: cannot read '" + path + "'");
  std::vector<blockers::Sphere> out;
  std::string line;
  int number = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::string where = path + ":" + std::to_string(number) + ": ";
    if (trimmed_lower(line).empty() || line[line.find_first_not_of(" \t")] == '#') continue;
    if (!header) {
      if (trimmed_lower(line) != "x,y,z,radius")
        throw std::invalid_argument(where + "the header must be x,y,z,radius (got '" + line.substr(0, 60) + "')");
      header = true;
      continue;
    }
    std::vector<std::string> cells;
    std::stringstream split(line);
    for (std::string cell; std::getline(split, cell, ',');) cells.push_back(cell);
    if (cells.size() != 4) throw std::invalid_argument(where + "expected 4 values x,y,z,radius");
    std::array<double, 4> v{};
    for (int k = 0; k < 4; ++k) {
      std::size_t used = 0;
      try {
        v[k] = std::stod(cells[k], &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || !std::isfinite(v[k]) || cells[k].find_first_not_of(" \t", used) != std::string::npos)
        throw std::invalid_argument(where + "'" + cells[k].substr(0, 40) + "' is not a finite number");
    }
    if (!(v[3] > 0.0)) throw std::invalid_argument(where + "the radius must be > 0");
    if (out.size() == kMaxSpheres)
      throw std::invalid_argument(path + ": more than " + std::to_string(kMaxSpheres) + " spheres");
    out.push_back({{v[0], v[1], v[2]}, v[3]});
  }
  if (!header) throw std::invalid_argument("--spheres: '" + path + "' is empty (expected the header x,y,z,radius)");
  if (out.empty()) throw std::invalid_argument("--spheres: '" + path + "' has a header but no spheres");
  return out;
}

glm::dvec2 texel_of(const terrain::HeightField& field, double x, double y) {
  const auto& g = field.georef.geotransform;
  if (!field.georef.has_geotransform || g[2] != 0.0 || g[4] != 0.0) return {x, y};
  return {(x - g[0]) / g[1] - 0.5, (y - g[3]) / g[5] - 0.5};
}

std::vector<blockers::Sphere> to_field_frame(const terrain::HeightField& field,
                                             const std::vector<blockers::Sphere>& crs) {
  std::vector<blockers::Sphere> out;
  out.reserve(crs.size());
  for (const auto& s : crs) {
    const glm::dvec2 t = texel_of(field, s.centre.x, s.centre.y);
    const int row = std::clamp(static_cast<int>(std::lround(t.y)), 0, field.height - 1);
    out.push_back({{t.x * field.dx(row), -t.y * field.dy, s.centre.z}, s.radius});
  }
  return out;
}

}  // namespace skylit::app::shade
