// The built-in synthetic scene as the commands that place things on it see it: the
// heights of terrain::make_synthetic_terrain, georeferenced in UTM zone 32N (EPSG:32632,
// an arbitrary place in the Alps) so that the sun has a place and the sample track
// (data/tracks/sample_glider.igc) lands on it. `skylit scene` writes exactly this.
#pragma once

#include "terrain/height_field.h"

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace skylit::app {

// Throws std::runtime_error when GDAL/PROJ cannot build the CRS (proj-data missing).
terrain::HeightField make_georeferenced_scene(int size, std::uint64_t seed);

// The viewer's field: INPUT DEM(s) (a mosaic when several), or with `synthetic` the scene
// above; the reader's warnings go to `warnings` ("<who>: warning: …") unless null.
// Throws std::invalid_argument for both or neither.
terrain::HeightField load_dems_or_scene(const std::vector<std::string>& inputs, bool synthetic, int scene_size,
                                        std::uint64_t seed, std::ostream* warnings, const std::string& who);

}  // namespace skylit::app
