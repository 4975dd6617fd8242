// Wavefront OBJ reading and writing (mesh_io.h).
#include "flight/mesh_io.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string_view>

namespace skylit::flight {
namespace {

[[noreturn]] void fail_at(const std::string& path, long line, const std::string& why) {
  throw MeshError(path + ":" + std::to_string(line) + ": " + why);
}

bool is_binary_byte(unsigned char c) { return c == 0 || (c < 0x20 && c != '\t' && c != '\r' && c != '\f' && c != '\v'); }

std::vector<std::string_view> tokens(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    std::size_t j = i;
    while (j < s.size() && !std::isspace(static_cast<unsigned char>(s[j]))) ++j;
    if (j > i) out.push_back(s.substr(i, j - i));
    i = j;
  }
  return out;
}

template <class T>
bool parse_number(std::string_view s, T& v) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return ec == std::errc() && end == s.data() + s.size();
}

}  // namespace

Mesh read_obj(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MeshError("cannot read mesh '" + path + "'");
  Mesh mesh;
  // Positive indices may in principle name later vertices: check them once all are read.
  struct PendingFace {
    long line;
    std::vector<long> indices;
  };
  std::vector<PendingFace> faces;
  std::string text;
  long line_no = 0;
  while (std::getline(in, text)) {
    ++line_no;
    if (std::any_of(text.begin(), text.end(), [](char c) { return is_binary_byte(static_cast<unsigned char>(c)); }))
      fail_at(path, line_no, "binary data: not a text OBJ file");
    const std::string_view line = std::string_view(text).substr(0, text.find('#'));
    const auto tok = tokens(line);
    if (tok.empty()) continue;
    if (tok[0] == "v") {
      glm::dvec3 p;
      if (tok.size() < 4 || !parse_number(tok[1], p.x) || !parse_number(tok[2], p.y) || !parse_number(tok[3], p.z))
        fail_at(path, line_no, "a vertex needs three numbers: 'v x y z'");
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) fail_at(path, line_no, "vertex not finite");
      mesh.vertices.push_back(p);
    } else if (tok[0] == "f") {
      if (tok.size() < 4) fail_at(path, line_no, "a face needs at least three vertices");
      PendingFace f{line_no, {}};
      for (std::size_t k = 1; k < tok.size(); ++k) {
        long idx;
        if (!parse_number(tok[k].substr(0, tok[k].find('/')), idx) || idx == 0)
          fail_at(path, line_no, "bad face index '" + std::string(tok[k]) + "'");
        if (idx < 0) {  // relative to the vertices read so far
          idx += static_cast<long>(mesh.vertices.size()) + 1;
          if (idx < 1) fail_at(path, line_no, "face index " + std::string(tok[k]) + " before the first vertex");
        }
        f.indices.push_back(idx);
      }
      faces.push_back(std::move(f));
    }
  }
  const long n = static_cast<long>(mesh.vertices.size());
  for (const auto& f : faces) {
    for (long idx : f.indices)
      if (idx > n) fail_at(path, f.line, "face index " + std::to_string(idx) + " outside 1.." + std::to_string(n));
    for (std::size_t k = 1; k + 1 < f.indices.size(); ++k)
      mesh.triangles.push_back({static_cast<std::uint32_t>(f.indices[0] - 1), static_cast<std::uint32_t>(f.indices[k] - 1),
                                static_cast<std::uint32_t>(f.indices[k + 1] - 1)});
  }
  if (mesh.triangles.empty()) throw MeshError(path + ": no faces (an OBJ mesh needs 'v' and 'f' lines)");
  return mesh;
}

std::string obj_text(const Mesh& mesh, const std::string& comment) {
  std::ostringstream out;
  std::istringstream lines(comment);
  for (std::string l; std::getline(lines, l);) out << "# " << l << "\n";
  char buf[96];
  for (const auto& v : mesh.vertices) {
    std::snprintf(buf, sizeof buf, "v %.9g %.9g %.9g\n", v.x, v.y, v.z);
    out << buf;
  }
  for (const auto& t : mesh.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  return out.str();
}

Mesh read_mesh(const std::string& path) {
  std::string ext = path.substr(path.find_last_of('.') == std::string::npos ? path.size() : path.find_last_of('.'));
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".obj") return read_obj(path);
  if (ext == ".ply") return read_ply(path);
  throw MeshError("mesh '" + path + "': unknown format (expected .obj or .ply)");
}

}  // namespace skylit::flight
