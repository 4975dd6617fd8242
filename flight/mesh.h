// A triangle mesh of an aircraft in its body frame (x forward, y left, z up, metres):
// vertices and counter-clockwise (outward-facing) triangles. A mesh may hold several
// closed shells that overlap (a wing through a fuselage); "inside" means inside any of
// them (non-zero winding number), so the solid the mesh stands for is their union.
#pragma once

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace skylit::flight {

// Bad mesh input (reader errors name the file and line) or a mesh that cannot be used.
class MeshError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Bounds {
  glm::dvec3 lo{0.0}, hi{0.0};
  glm::dvec3 size() const { return hi - lo; }
  double volume() const { return size().x * size().y * size().z; }
};

struct Mesh {
  std::vector<glm::dvec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;

  // Appends `other`'s vertices and triangles (a second shell).
  void append(const Mesh& other);
};

Bounds bounds(const Mesh& mesh);

// Σ over triangles of a·(b×c)/6 (divergence theorem): the enclosed volume of one closed,
// outward-oriented, non-self-intersecting shell. Overlapping shells count their overlap
// twice, so for their union use a Monte Carlo estimate over `MeshInside`.
double signed_volume(const Mesh& mesh);

// True when every directed edge a→b is matched by exactly one b→a: each edge borders two
// triangles that agree on orientation (closed and consistently oriented, hence watertight).
bool is_closed(const Mesh& mesh);

// Throws MeshError ("<what>: …", one line) unless the mesh has triangles, finite
// vertices, valid indices and is closed; `what` names the mesh in the message.
void check_closed_mesh(const Mesh& mesh, const std::string& what);

// Reverses every triangle's winding (turns inward-facing shells outward).
void flip_orientation(Mesh& mesh);

}  // namespace skylit::flight
