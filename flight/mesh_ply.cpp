// PLY reading (mesh_io.h): the header's elements and properties, then the body in
// ascii (one element per line) or binary_little_endian.
#include "flight/mesh_io.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

namespace skylit::flight {
namespace {

enum class Scalar { i8, u8, i16, u16, i32, u32, f32, f64 };

bool scalar_named(const std::string& s, Scalar& out) {
  static const std::pair<const char*, Scalar> names[] = {
      {"char", Scalar::i8},   {"int8", Scalar::i8},     {"uchar", Scalar::u8},   {"uint8", Scalar::u8},
      {"short", Scalar::i16}, {"int16", Scalar::i16},   {"ushort", Scalar::u16}, {"uint16", Scalar::u16},
      {"int", Scalar::i32},   {"int32", Scalar::i32},   {"uint", Scalar::u32},   {"uint32", Scalar::u32},
      {"float", Scalar::f32}, {"float32", Scalar::f32}, {"double", Scalar::f64}, {"float64", Scalar::f64}};
  for (const auto& [name, type] : names)
    if (s == name) return out = type, true;
  return false;
}

std::size_t scalar_size(Scalar s) {
  switch (s) {
    case Scalar::i8: case Scalar::u8: return 1;
    case Scalar::i16: case Scalar::u16: return 2;
    case Scalar::i32: case Scalar::u32: case Scalar::f32: return 4;
    case Scalar::f64: return 8;
  }
  return 0;
}

struct Property {
  std::string name;
  bool is_list = false;
  Scalar count_type = Scalar::u8, value_type = Scalar::f32;
};

struct Element {
  std::string name;
  long long count = 0;
  std::vector<Property> properties;
};

// Reads one scalar of the body, in ascii or little-endian binary.
class BodyReader {
 public:
  BodyReader(std::istream& in, bool binary, const std::string& path) : in_(in), binary_(binary), path_(path) {}

  double read(Scalar type) {
    if (!binary_) {
      double v;
      if (!(in_ >> v)) throw MeshError(path_ + ": the data ends early or holds a non-number");
      return v;
    }
    unsigned char b[8];
    const std::size_t n = scalar_size(type);
    if (!in_.read(reinterpret_cast<char*>(b), static_cast<std::streamsize>(n)))
      throw MeshError(path_ + ": the binary data ends early");
    static_assert(std::endian::native == std::endian::little, "PLY binary reading assumes a little-endian host");
    switch (type) {
      case Scalar::i8: return static_cast<std::int8_t>(b[0]);
      case Scalar::u8: return b[0];
      case Scalar::i16: { std::int16_t v; std::memcpy(&v, b, 2); return v; }
      case Scalar::u16: { std::uint16_t v; std::memcpy(&v, b, 2); return v; }
      case Scalar::i32: { std::int32_t v; std::memcpy(&v, b, 4); return v; }
      case Scalar::u32: { std::uint32_t v; std::memcpy(&v, b, 4); return v; }
      case Scalar::f32: { float v; std::memcpy(&v, b, 4); return v; }
      case Scalar::f64: { double v; std::memcpy(&v, b, 8); return v; }
    }
    return 0.0;
  }

 private:
  std::istream& in_;
  bool binary_;
  const std::string& path_;
};

// The largest element count believed without reading it: 100 M rows is far beyond any
// aircraft mesh, and a garbage header must not reserve gigabytes.
constexpr long long kMaxElementCount = 100'000'000;
constexpr std::size_t kMaxFaceVertices = 1000;

}  // namespace

Mesh read_ply(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MeshError("cannot read mesh '" + path + "'");
  auto fail = [&](long line, const std::string& why) -> MeshError {
    return MeshError(path + ":" + std::to_string(line) + ": " + why);
  };
  std::string line;
  long line_no = 1;
  if (!std::getline(in, line) || (line != "ply" && line != "ply\r")) throw fail(1, "not a PLY file (no 'ply' line)");
  bool binary = false, have_format = false;
  std::vector<Element> elements;
  while (true) {
    ++line_no;
    if (!std::getline(in, line)) throw fail(line_no, "the header has no 'end_header'");
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream words(line);
    std::string key;
    words >> key;
    if (key == "end_header") break;
    if (key.empty() || key == "comment" || key == "obj_info") continue;
    if (key == "format") {
      std::string fmt;
      words >> fmt;
      if (fmt == "ascii") binary = false;
      else if (fmt == "binary_little_endian") binary = true;
      else throw fail(line_no, "format '" + fmt + "' not supported (ascii or binary_little_endian)");
      have_format = true;
    } else if (key == "element") {
      Element e;
      if (!(words >> e.name >> e.count) || e.count < 0 || e.count > kMaxElementCount)
        throw fail(line_no, "bad element line '" + line + "'");
      elements.push_back(e);
    } else if (key == "property") {
      if (elements.empty()) throw fail(line_no, "a property before any element");
      Property p;
      std::string type;
      words >> type;
      if (type == "list") {
        std::string ct, vt;
        p.is_list = true;
        if (!(words >> ct >> vt >> p.name) || !scalar_named(ct, p.count_type) || !scalar_named(vt, p.value_type))
          throw fail(line_no, "bad list property '" + line + "'");
      } else if (!scalar_named(type, p.value_type) || !(words >> p.name)) {
        throw fail(line_no, "bad property '" + line + "'");
      }
      elements.back().properties.push_back(p);
    } else {
      throw fail(line_no, "unknown header line '" + line + "'");
    }
  }
  if (!have_format) throw fail(line_no, "the header has no 'format' line");

  Mesh mesh;
  BodyReader body(in, binary, path);
  long long vertex_count = -1;
  for (const Element& e : elements) {
    const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
    int ix = -1, iy = -1, iz = -1, ifaces = -1;
    for (int k = 0; k < static_cast<int>(e.properties.size()); ++k) {
      const auto& name = e.properties[k].name;
      if (is_vertex && !e.properties[k].is_list) {
        if (name == "x") ix = k;
        if (name == "y") iy = k;
        if (name == "z") iz = k;
      }
      if (is_face && e.properties[k].is_list && (name == "vertex_indices" || name == "vertex_index")) ifaces = k;
    }
    if (is_vertex && (ix < 0 || iy < 0 || iz < 0)) throw MeshError(path + ": the vertex element lacks x, y or z");
    if (is_face && ifaces < 0) throw MeshError(path + ": the face element has no vertex_indices list");
    if (is_face && vertex_count < 0) throw MeshError(path + ": faces come before the vertices");
    if (is_vertex) {
      vertex_count = e.count;
      mesh.vertices.reserve(static_cast<std::size_t>(std::min<long long>(e.count, 1'000'000)));
    }
    std::vector<std::uint32_t> poly;
    for (long long row = 0; row < e.count; ++row) {
      glm::dvec3 p(0.0);
      for (int k = 0; k < static_cast<int>(e.properties.size()); ++k) {
        const Property& prop = e.properties[k];
        if (!prop.is_list) {
          const double v = body.read(prop.value_type);
          if (k == ix) p.x = v;
          if (k == iy) p.y = v;
          if (k == iz) p.z = v;
          continue;
        }
        const double n = body.read(prop.count_type);
        if (!(n >= 0 && n <= kMaxFaceVertices) || n != std::floor(n))
          throw MeshError(path + ": bad list length in " + e.name + " " + std::to_string(row));
        poly.clear();
        for (int j = 0; j < static_cast<int>(n); ++j) {
          const double idx = body.read(prop.value_type);
          if (k == ifaces) {
            if (!(idx >= 0 && idx < static_cast<double>(vertex_count)) || idx != std::floor(idx))
              throw MeshError(path + ": face " + std::to_string(row) + " has vertex index " + std::to_string(idx) +
                              " outside 0.." + std::to_string(vertex_count - 1));
            poly.push_back(static_cast<std::uint32_t>(idx));
          }
        }
        if (k == ifaces) {
          if (poly.size() < 3) throw MeshError(path + ": face " + std::to_string(row) + " has fewer than three vertices");
          for (std::size_t j = 1; j + 1 < poly.size(); ++j) mesh.triangles.push_back({poly[0], poly[j], poly[j + 1]});
        }
      }
      if (is_vertex) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
          throw MeshError(path + ": vertex " + std::to_string(row) + " is not finite");
        mesh.vertices.push_back(p);
      }
    }
  }
  if (mesh.triangles.empty()) throw MeshError(path + ": no faces");
  return mesh;
}

}  // namespace skylit::flight
