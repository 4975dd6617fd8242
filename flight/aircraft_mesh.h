// Procedural aircraft meshes (no downloads): closed shells for fuselage, wings, tails,
// nacelles, rotor disc, balloon envelope, unioned by overlap (mesh.h), in the body
// frame. Each preset's dimensions follow public figures, stated in aircraft_mesh.cpp.
#pragma once

#include "flight/mesh.h"

#include <string>
#include <vector>

namespace skylit::flight {

struct AircraftPreset {
  std::string name;     // glider, light-single, airliner, helicopter, balloon
  std::string model;    // the type whose public figures it follows
  int suggested_k = 30; // spheres in the shipped set
};

const std::vector<AircraftPreset>& aircraft_presets();

// Throws std::invalid_argument naming the presets for an unknown name.
Mesh make_aircraft_mesh(const std::string& name);

// Parts, exposed for tests and new presets. A body of revolution-like loft: elliptic
// sections (width, height) centred at height z, along x.
struct FuselageStation {
  double x, width, height, z;
};
Mesh make_fuselage(const std::vector<FuselageStation>& stations);

// A lifting surface through airfoil sections (symmetric NACA 4-digit thickness with
// the given thickness ratio). For a wing the span runs along y and `span` is y; for a
// fin it runs along z and `span` is z, with `offset` the section's y (else its z).
struct SurfaceStation {
  double span, x_le, chord, thickness, offset;
};
enum class SpanAxis { y, z };
Mesh make_surface(const std::vector<SurfaceStation>& stations, SpanAxis axis);

}  // namespace skylit::flight
