// Lighting for tests that name the sun by its angles (CPU and GPU tests alike).
#pragma once

#include "shading/lighting.h"

#include <optional>
#include <string>

namespace skylit::testing {

// The sun at (azimuth, elevation) in degrees under `sky` (lighting.h's names).
inline shading::Lighting sun_at(double azimuth_deg, double elevation_deg, const std::string& sky = "uniform") {
  shading::LightingRequest r;
  r.sun_azimuth_deg = azimuth_deg;
  r.sun_elevation_deg = elevation_deg;
  r.sky = sky;
  return shading::resolve_lighting(r, std::nullopt).lighting;
}

}  // namespace skylit::testing
