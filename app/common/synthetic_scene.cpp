#include "app/common/synthetic_scene.h"

#include "terrain/dem_reader.h"
#include "terrain/synthetic.h"

#include <ogr_spatialref.h>

#include <stdexcept>
#include <string>

namespace skylit::app {
namespace {

// The scene's metres need a projected CRS to be read back as metres.
constexpr int kSceneEpsg = 32632;
constexpr double kSceneEasting = 400000.0, kSceneNorthing = 5200000.0;

}  // namespace

terrain::HeightField make_georeferenced_scene(int size, std::uint64_t seed) {
  terrain::SyntheticOptions opt;
  opt.width = opt.height = size;
  opt.seed = seed;
  terrain::HeightField field = terrain::make_synthetic_terrain(opt);
  OGRSpatialReference srs;
  if (srs.importFromEPSG(kSceneEpsg) != OGRERR_NONE)
    throw std::runtime_error("GDAL/PROJ cannot build EPSG:" + std::to_string(kSceneEpsg) + " (is proj-data installed?)");
  char* wkt = nullptr;
  srs.exportToWkt(&wkt);
  field.georef.crs_wkt = wkt;
  CPLFree(wkt);
  field.georef.geotransform = {kSceneEasting, opt.spacing, 0.0, kSceneNorthing, 0.0, -opt.spacing};
  field.georef.has_geotransform = true;
  field.georef.geographic = false;
  return field;
}

terrain::HeightField load_dems_or_scene(const std::vector<std::string>& inputs, bool synthetic, int scene_size,
                                        std::uint64_t seed, std::ostream* warnings, const std::string& who) {
  if (synthetic) {
    if (!inputs.empty()) throw std::invalid_argument("give either INPUT files or --synthetic, not both");
    return make_georeferenced_scene(scene_size, seed);
  }
  if (inputs.empty()) throw std::invalid_argument("no INPUT DEM given (or use --synthetic for the built-in scene)");
  auto r = inputs.size() == 1 ? terrain::read_dem(inputs.front(), {}) : terrain::read_dem(inputs, {});
  if (warnings)
    for (const auto& w : r.warnings) *warnings << who << ": warning: " << w << "\n";
  return std::move(r.field);
}

}  // namespace skylit::app
