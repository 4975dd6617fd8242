#include "flight/aircraft_mesh.h"

#include "flight/mesh_shapes.h"

#include <glm/trigonometric.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace skylit::flight {
namespace {

constexpr int kRingPoints = 24;     // around a fuselage or nacelle section
constexpr int kChordPoints = 12;    // per airfoil side

// Half-thickness of the NACA 4-digit symmetric section at chord fraction x, for
// thickness ratio t (the open-trailing-edge coefficient −0.1015, so the edge keeps a
// sliver of thickness and the upper and lower points never coincide).
double naca_half_thickness(double x, double t) {
  return 5.0 * t * (0.2969 * std::sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x - 0.1015 * x * x * x * x);
}

// Cosine-spaced chord fractions in (0, 1]: dense at the rounded leading edge.
double chord_fraction(int k) { return 0.5 * (1.0 - std::cos(std::numbers::pi * k / kChordPoints)); }

std::vector<glm::dvec3> ellipse_ring(double x, double width, double height, double z) {
  std::vector<glm::dvec3> ring;
  for (int i = 0; i < kRingPoints; ++i) {
    const double t = 2.0 * std::numbers::pi * i / kRingPoints;
    ring.push_back({x, 0.5 * width * std::cos(t), z + 0.5 * height * std::sin(t)});
  }
  return ring;
}

// A body of revolution about the vertical line through (x, y): (z, radius) stations.
Mesh revolved_about_z(double x, double y, const std::vector<std::pair<double, double>>& stations, int points) {
  std::vector<std::vector<glm::dvec3>> rings;
  for (const auto& [z, r] : stations) {
    std::vector<glm::dvec3> ring;
    for (int i = 0; i < points; ++i) {
      const double t = 2.0 * std::numbers::pi * i / points;
      ring.push_back({x + r * std::cos(t), y + r * std::sin(t), z});
    }
    rings.push_back(ring);
  }
  return loft(rings);
}

// A symmetric surface (wing, tailplane) from its root and outboard stations given for
// the left half (span ≥ 0), mirrored to the right; dihedral raises the offset with span.
Mesh mirrored_wing(const std::vector<SurfaceStation>& left_from_root) {
  std::vector<SurfaceStation> all;
  for (auto it = left_from_root.rbegin(); it != left_from_root.rend(); ++it) all.push_back(*it);
  for (std::size_t i = 1; i < left_from_root.size(); ++i) {
    SurfaceStation s = left_from_root[i];
    s.span = -s.span;
    all.push_back(s);
  }
  return make_surface(all, SpanAxis::y);
}

// Sections of a straight-tapered half wing: root at y = 0, tip at `semispan`, leading
// edge swept back by `sweep_le_deg`, dihedral raising the tip, thickness tapering.
std::vector<SurfaceStation> tapered_half(double semispan, double root_x_le, double root_chord, double tip_chord,
                                         double sweep_le_deg, double dihedral_deg, double z_root, double t_root,
                                         double t_tip) {
  return {{0.0, root_x_le, root_chord, t_root, z_root},
          {semispan, root_x_le - semispan * std::tan(glm::radians(sweep_le_deg)), tip_chord, t_tip,
           z_root + semispan * std::tan(glm::radians(dihedral_deg))}};
}

Mesh cylinder_z(double x, double y, double z0, double z1, double radius, int sides) {
  return transformed(make_prism(radius, z1 - z0, sides), glm::dmat3(1.0), {x, y, z0});
}

// Glider after the Schleicher ASW 28 (15 m class): span 15.0 m, length 6.59 m, wing area
// 10.5 m², height 1.3 m. Origin: the wing root's quarter chord on the fuselage axis.
Mesh glider() {
  Mesh m = make_fuselage({{1.85, 0.06, 0.06, -0.05}, {1.5, 0.45, 0.55, 0.0}, {0.9, 0.62, 0.80, 0.05},
                          {0.0, 0.60, 0.74, 0.05}, {-1.0, 0.40, 0.50, 0.10}, {-2.5, 0.22, 0.28, 0.15},
                          {-4.5, 0.13, 0.20, 0.20}, {-4.74, 0.05, 0.08, 0.20}});
  m.append(mirrored_wing(tapered_half(7.5, 0.24, 0.95, 0.40, 1.1, 3.0, 0.22, 0.14, 0.13)));
  m.append(mirrored_wing(tapered_half(1.2, -4.05, 0.62, 0.40, 8.0, 0.0, 1.28, 0.10, 0.10)));  // T-tail
  m.append(make_surface({{0.1, -3.75, 1.00, 0.12, 0.0}, {1.32, -4.10, 0.62, 0.11, 0.0}}, SpanAxis::z));
  return m;
}

// Light single after the Cessna 172S: span 11.0 m, length 8.28 m, height 2.72 m, wing
// area 16.2 m² (chord 1.63 m inboard, 1.13 m at the tip), tailplane span 3.45 m, high wing.
// Origin: the wing's quarter chord on the fuselage axis.
Mesh light_single() {
  Mesh m = make_fuselage({{2.05, 0.12, 0.12, 0.0}, {1.75, 0.80, 0.80, 0.0}, {1.0, 1.05, 1.25, 0.05},
                          {0.0, 1.10, 1.45, 0.10}, {-1.5, 0.90, 1.20, 0.10}, {-3.5, 0.45, 0.72, 0.25},
                          {-5.8, 0.20, 0.36, 0.35}, {-6.23, 0.06, 0.12, 0.35}});
  const double z = 0.82, dihedral = std::tan(glm::radians(1.73));
  m.append(mirrored_wing({{0.0, 0.41, 1.63, 0.12, z}, {2.5, 0.41, 1.63, 0.12, z + 2.5 * dihedral},
                          {5.5, 0.28, 1.13, 0.12, z + 5.5 * dihedral}}));
  m.append(mirrored_wing(tapered_half(1.725, -5.05, 1.20, 0.80, 12.0, 0.0, 0.35, 0.09, 0.09)));
  m.append(make_surface({{0.3, -4.50, 1.70, 0.10, 0.0}, {1.95, -5.45, 0.85, 0.10, 0.0}}, SpanAxis::z));
  return m;
}

// Airliner after the Airbus A320-200: span 34.1 m (35.8 m with sharklets), length
// 37.57 m, height 11.76 m, fuselage diameter 3.95 m, wing area 122.6 m² with a 25°
// quarter-chord sweep, tailplane span 12.45 m, CFM56-5B nacelles (≈ 2.4 m across,
// ≈ 4.4 m long) 5.75 m either side. Origin: near the wing root's quarter chord.
Mesh airliner() {
  Mesh m = make_fuselage({{16.0, 0.3, 0.3, -0.3}, {15.3, 1.7, 1.7, -0.2}, {14.0, 3.3, 3.4, -0.05},
                          {12.0, 3.95, 4.10, 0.0}, {-10.0, 3.95, 4.10, 0.0}, {-15.0, 3.0, 3.4, 0.4},
                          {-19.0, 1.6, 2.0, 1.0}, {-21.57, 0.3, 0.5, 1.3}});
  const double sweep = 27.0, dihedral = std::tan(glm::radians(5.0)), x_le = 2.0, z = -1.2;
  auto le = [&](double y) { return x_le - y * std::tan(glm::radians(sweep)); };
  m.append(mirrored_wing({{0.0, x_le, 7.0, 0.15, z}, {6.3, le(6.3), 4.3, 0.13, z + 6.3 * dihedral},
                          {17.05, le(17.05), 1.5, 0.11, z + 17.05 * dihedral}}));
  m.append(mirrored_wing(tapered_half(6.225, -15.6, 3.8, 1.3, 32.0, 6.0, 0.9, 0.10, 0.10)));
  m.append(make_surface({{1.6, -14.3, 6.0, 0.10, 0.0}, {7.8, -18.7, 2.2, 0.10, 0.0}}, SpanAxis::z));
  for (double y : {5.75, -5.75}) {
    Mesh nacelle = make_fuselage({{3.9, 2.0, 2.0, 0.0}, {3.6, 2.37, 2.37, 0.0}, {1.6, 2.3, 2.3, 0.0},
                                  {-0.2, 1.5, 1.5, 0.0}, {-0.5, 0.8, 0.8, 0.0}});
    m.append(transformed(nacelle, glm::dmat3(1.0), {0.0, y, -2.0}));
  }
  return m;
}

// Helicopter after the Airbus H125 (AS350 B3): main rotor 10.69 m across, fuselage
// 10.93 m long, height 3.34 m, cabin ≈ 1.8 m wide. The rotor is a disc 0.15 m thick.
// Origin: on the rotor mast at mid-cabin height.
Mesh helicopter() {
  Mesh m = make_fuselage({{2.0, 0.3, 0.3, -0.3}, {1.7, 1.3, 1.3, -0.2}, {0.8, 1.8, 1.8, 0.0},
                          {-1.0, 1.7, 1.9, 0.1}, {-2.3, 0.9, 1.2, 0.3}});
  m.append(make_fuselage({{-2.0, 0.70, 0.70, 0.40}, {-5.0, 0.45, 0.45, 0.50}, {-8.6, 0.28, 0.28, 0.60},
                          {-8.93, 0.10, 0.10, 0.60}}));                              // tail boom
  m.append(make_surface({{0.4, -7.9, 1.0, 0.12, 0.0}, {1.7, -8.5, 0.6, 0.12, 0.0}}, SpanAxis::z));  // fin
  m.append(mirrored_wing(tapered_half(1.0, -6.6, 0.5, 0.4, 10.0, 0.0, 0.5, 0.12, 0.12)));          // stabiliser
  m.append(cylinder_z(0.0, 0.0, 0.8, 1.6, 0.25, 16));                                // mast and head
  m.append(cylinder_z(0.0, 0.0, 1.6, 1.75, 10.69 / 2.0, 48));                        // rotor disc
  return m;
}

// Hot-air balloon after the Cameron O-120 (3400 m³): envelope 20 m tall, 18.8 m across,
// narrowing to a 3.2 m throat; a 1.6 × 1.2 × 1.1 m basket hung 4 m below the throat.
// Origin: the envelope's centre.
Mesh balloon() {
  Mesh m = revolved_about_z(0.0, 0.0,
                            {{-10.0, 1.6}, {-8.0, 4.0}, {-5.0, 7.0}, {-2.0, 8.8}, {1.0, 9.4}, {4.0, 8.9},
                             {6.5, 7.3}, {8.5, 4.8}, {9.6, 2.4}, {10.0, 0.4}},
                            32);
  m.append(make_box({-0.8, -0.6, -15.1}, {0.8, 0.6, -14.0}));
  return m;
}

}  // namespace

Mesh make_fuselage(const std::vector<FuselageStation>& stations) {
  std::vector<std::vector<glm::dvec3>> rings;
  for (const auto& s : stations) rings.push_back(ellipse_ring(s.x, s.width, s.height, s.z));
  return loft(rings);
}

Mesh make_surface(const std::vector<SurfaceStation>& stations, SpanAxis axis) {
  std::vector<std::vector<glm::dvec3>> rings;
  for (const auto& s : stations) {
    std::vector<glm::dvec3> ring;
    auto point = [&](double xc, double side) {
      const double x = s.x_le - xc * s.chord, across = side * naca_half_thickness(xc, s.thickness) * s.chord;
      ring.push_back(axis == SpanAxis::y ? glm::dvec3(x, s.span, s.offset + across)
                                         : glm::dvec3(x, s.offset + across, s.span));
    };
    for (int k = 1; k <= kChordPoints; ++k) point(chord_fraction(k), 1.0);
    for (int k = kChordPoints; k >= 1; --k) point(chord_fraction(k), -1.0);
    rings.push_back(ring);
  }
  return loft(rings);
}

const std::vector<AircraftPreset>& aircraft_presets() {
  static const std::vector<AircraftPreset> presets = {
      {"glider", "Schleicher ASW 28 (15 m)", 30},
      {"light-single", "Cessna 172S", 30},
      {"airliner", "Airbus A320-200", 30},
      {"helicopter", "Airbus H125 (AS350 B3)", 30},
      {"balloon", "Cameron O-120", 12},
  };
  return presets;
}

Mesh make_aircraft_mesh(const std::string& name) {
  if (name == "glider") return glider();
  if (name == "light-single") return light_single();
  if (name == "airliner") return airliner();
  if (name == "helicopter") return helicopter();
  if (name == "balloon") return balloon();
  std::string names;
  for (const auto& p : aircraft_presets()) names += (names.empty() ? "" : ", ") + p.name;
  throw std::invalid_argument("unknown aircraft '" + name + "' (one of " + names + ")");
}

}  // namespace skylit::flight
