#include "app/shade/hillshade_args.h"

#include <CLI/CLI.hpp>

#include <stdexcept>

namespace skylit::app::shade {

void add_hillshade_options(CLI::App& cmd, HillshadeArgs& args) {
  cmd.add_option("--alg", args.alg, "Gradient of -p hillshade: Horn | ZevenbergenThorne (gdaldem -alg)")
      ->check(CLI::IsMember({"Horn", "ZevenbergenThorne"}))
      ->capture_default_str();
  cmd.add_flag("--combined", args.combined, "-p hillshade: slope-combined shading (gdaldem -combined)");
  cmd.add_flag("--multidirectional", args.multidirectional, "-p hillshade: four light directions (gdaldem -multidirectional)");
  cmd.add_flag("--igor", args.igor, "-p hillshade: Igor's shading, no illumination model (gdaldem -igor)");
}

relief::HillshadeOptions hillshade_options(const HillshadeArgs& args, double z, std::optional<double> azimuth_deg,
                                           std::optional<double> altitude_deg, bool compute_edges) {
  if (int(args.combined) + int(args.multidirectional) + int(args.igor) > 1)
    throw std::invalid_argument("give at most one of --combined, --multidirectional and --igor");
  if (args.multidirectional && azimuth_deg)
    throw std::invalid_argument("--multidirectional takes no --azimuth (-az): it lights from 225, 270, 315 and 360");
  relief::HillshadeOptions o;
  o.gradient = args.alg == "ZevenbergenThorne" ? relief::Gradient::ZevenbergenThorne : relief::Gradient::Horn;
  o.variant = args.combined           ? relief::HillshadeVariant::Combined
              : args.multidirectional ? relief::HillshadeVariant::MultiDirectional
              : args.igor             ? relief::HillshadeVariant::Igor
                                      : relief::HillshadeVariant::Regular;
  o.z = z;
  if (azimuth_deg) o.azimuth_deg = *azimuth_deg;
  if (altitude_deg) o.altitude_deg = *altitude_deg;
  o.compute_edges = compute_edges;
  return o;
}

}  // namespace skylit::app::shade
