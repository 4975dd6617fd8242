// The sphere sets the project ships (data/aircraft/<name>.json), found by name, or any
// set file given by its path.
#pragma once

#include "flight/sphere_set.h"

#include <string>
#include <vector>

namespace skylit::flight {

// The source tree's data/aircraft (SKYLIT_DATA_DIR, set by CMake).
std::string aircraft_data_dir();

// Names of the shipped sets (the .json files there), sorted.
std::vector<std::string> shipped_aircraft();

// A path (it contains '/' or ends in .json) is read as a file; anything else is looked
// up as a shipped name. Throws SphereSetError naming the shipped sets for an unknown name.
SphereSet load_aircraft(const std::string& name_or_path);

}  // namespace skylit::flight
