#include "app/common/lighting_args.h"

#include "terrain/geolocation.h"

#include <CLI/CLI.hpp>

#include <stdexcept>

namespace skylit::app {

void add_lighting_options(CLI::App& cmd, LightingArgs& args, const std::string& time_help) {
  auto& l = args.request;
  cmd.add_option("--time", l.time, time_help);
  cmd.add_option("--lat", l.latitude_deg, "Latitude for --time, degrees north (default: the DEM's centre)");
  cmd.add_option("--lon", l.longitude_deg, "Longitude for --time, degrees east (default: the DEM's centre)");
  cmd.add_option("--sun-azimuth,--azimuth", l.sun_azimuth_deg,
                 "Sun azimuth, degrees from north clockwise (gdaldem -az; default 315 without --time)");
  cmd.add_option("--sun-elevation,--altitude", l.sun_elevation_deg,
                 "Sun elevation above the horizon, degrees (gdaldem -alt; default 45 without --time)");
  cmd.add_option("--sky", l.sky, "Sky: uniform | preetham | cie:<1..16> | an equirectangular .hdr/.exr map")
      ->capture_default_str();
  cmd.add_option("--turbidity", l.turbidity, "Clear-sky turbidity (sun DNI, sky level), 1.7..10")->capture_default_str();
  cmd.add_option("--sky-scale", l.sky_scale, "Multiplier of .hdr/.exr sky pixel values (to W m^-2 sr^-1)")
      ->capture_default_str();
  cmd.add_flag("--no-sun", args.no_sun,
               "Sky light only; with nothing else about the light, the classic uniform-sky relief "
               "(open flat ground white)");
  cmd.add_option("--tone", args.tone,
                 "8-bit tone curve of shaded: linear (codes proportional to irradiance, as gdaldem's hillshade), "
                 "srgb (a picture), auto (linear for grey skies, srgb for colour skies)")
      ->check(CLI::IsMember({"auto", "linear", "srgb"}))
      ->capture_default_str();
}

shading::ToneCurve tone_curve(const LightingArgs& args) {
  if (args.tone == "linear") return shading::ToneCurve::Linear;
  if (args.tone == "srgb") return shading::ToneCurve::Srgb;
  const auto kind = shading::parse_sky_spec(args.request.sky).kind;
  const bool colour = kind == shading::SkySpec::Kind::Preetham || kind == shading::SkySpec::Kind::EnvMap;
  return colour ? shading::ToneCurve::Srgb : shading::ToneCurve::Linear;
}

bool sky_only_default(const LightingArgs& args) {
  const auto& l = args.request;
  return args.no_sun && l.time.empty() && !l.sun_azimuth_deg && !l.sun_elevation_deg && l.sky == "uniform";
}

namespace {
std::optional<sky::Observer> centre_of(const terrain::HeightField& grid, float height) {
  const auto at = terrain::grid_centre_lat_lon(grid.georef, grid.width, grid.height);
  if (!at) return std::nullopt;
  return sky::Observer{at->latitude_deg, at->longitude_deg, height};
}
}  // namespace

std::optional<sky::Observer> dem_place(const terrain::HeightField& field) {
  return centre_of(field, field.at(field.width / 2, field.height / 2));
}

std::optional<sky::Observer> dem_place(const terrain::StagedDem& dem) {
  return centre_of(dem.outline(), dem.centre_height());
}

sky::Observer sun_place(const shading::LightingRequest& request, const terrain::HeightField& field) {
  if (request.latitude_deg && request.longitude_deg)
    return sky::Observer{*request.latitude_deg, *request.longitude_deg, request.height_m};
  if (const std::optional<sky::Observer> centre = dem_place(field)) return *centre;
  throw std::invalid_argument("the DEM has no CRS to place the sun: give --lat and --lon");
}

}  // namespace skylit::app
