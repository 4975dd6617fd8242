// The light options of the commands that shade (shade, tiles): --time and its place,
// the sun's angles, the sky, --no-sun and --tone, registered once here so that every
// front end spells and resolves them the same way.
#pragma once

#include "app/common/cli_fwd.h"

#include <optional>
#include <string>

#include "shading/lighting.h"
#include "shading/products.h"
#include "terrain/height_field.h"
#include "terrain/staged_dem.h"

namespace skylit::app {

struct LightingArgs {
  shading::LightingRequest request;
  bool no_sun = false;
  std::string tone = "auto";
};

// Registers --time (with `time_help`: a command says whether it takes series), --lat,
// --lon, --sun-azimuth/--azimuth, --sun-elevation/--altitude, --sky, --turbidity,
// --sky-scale, --no-sun and --tone.
void add_lighting_options(CLI::App& cmd, LightingArgs& args, const std::string& time_help);

// --tone auto: linear codes for a grey relief (a hillshade, as gdaldem stores it), the
// sRGB curve for a colour sky's picture.
shading::ToneCurve tone_curve(const LightingArgs& args);

// The library's default `shaded` (uniform sky of radiance 1, no sun: open flat ground
// white) is what --no-sun gives when nothing else about the light is asked for.
bool sky_only_default(const LightingArgs& args);

// The DEM's centre (WGS 84) and height there, for the sun's position; nullopt without a CRS.
std::optional<sky::Observer> dem_place(const terrain::HeightField& field);
std::optional<sky::Observer> dem_place(const terrain::StagedDem& dem);  // a DEM not held whole

// Where a clock's sun is seen from: the request's --lat/--lon (at its height), else the
// DEM's centre. Throws std::invalid_argument (one line) when there is neither.
sky::Observer sun_place(const shading::LightingRequest& request, const terrain::HeightField& field);

}  // namespace skylit::app
