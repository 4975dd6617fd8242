#include "flight/aircraft_catalog.h"

#include <algorithm>
#include <filesystem>

namespace skylit::flight {

std::string aircraft_data_dir() { return std::string(SKYLIT_DATA_DIR) + "/aircraft"; }

std::vector<std::string> shipped_aircraft() {
  namespace fs = std::filesystem;
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::directory_iterator it(aircraft_data_dir(), ec), end; !ec && it != end; it.increment(ec))
    if (it->path().extension() == ".json") names.push_back(it->path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

SphereSet load_aircraft(const std::string& name_or_path) {
  const bool is_path = name_or_path.find('/') != std::string::npos ||
                       (name_or_path.size() > 5 && name_or_path.ends_with(".json"));
  if (is_path) return read_sphere_set(name_or_path);
  const auto names = shipped_aircraft();
  if (std::find(names.begin(), names.end(), name_or_path) == names.end()) {
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    throw SphereSetError("unknown aircraft '" + name_or_path + "' (shipped: " + (list.empty() ? "none" : list) +
                         "; or give a path to a .json sphere set)");
  }
  return read_sphere_set(aircraft_data_dir() + "/" + name_or_path + ".json");
}

}  // namespace skylit::flight
