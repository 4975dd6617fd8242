// Mesh files: Wavefront OBJ (read and write) and PLY (read: ascii and
// binary_little_endian). Polygons are fan-triangulated. Every error is one line naming
// the file and, in text, the line: "wing.obj:12: face index 40 outside 1..36".
#pragma once

#include "flight/mesh.h"

#include <string>

namespace skylit::flight {

// Reads `v` and `f` statements (indices 1-based or negative = relative to the last
// vertex; `a/b/c` forms keep the position index); other statements are ignored.
Mesh read_obj(const std::string& path);

// Reads the `vertex` element's x, y, z and the `face` element's vertex_indices (or
// vertex_index) list; other elements and properties are skipped.
Mesh read_ply(const std::string& path);

// By extension (.obj, .ply, any case); throws MeshError for anything else.
Mesh read_mesh(const std::string& path);

// The text of an OBJ file holding `mesh` (1-based indices), with `comment` as a header.
std::string obj_text(const Mesh& mesh, const std::string& comment);

}  // namespace skylit::flight
