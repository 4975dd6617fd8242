// OBJ and PLY readers on small hand-written files (a unit cube as quads, a tetrahedron
// in binary PLY): geometry, fan triangulation, negative indices, and one-line errors
// that name the file and line.
#include "flight/mesh_io.h"

#include "terrain_test_util.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>

namespace skylit::flight {
namespace {

using terrain::testing::ScratchDir;

std::string write(const ScratchDir& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir.file(name), std::ios::binary) << text;
  return dir.file(name);
}

const char* kCubeVertices =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n";
// Outward (counter-clockwise seen from outside) quads of the unit cube.
const char* kCubeFaces = "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

std::string message_of(const std::string& path, Mesh (*reader)(const std::string&)) {
  try {
    reader(path);
  } catch (const MeshError& e) {
    return e.what();
  }
  return "";
}

TEST(ReadObj, CubeOfQuadsIsTwelveTrianglesOfUnitVolume) {
  ScratchDir dir;
  const Mesh m = read_obj(write(dir, "cube.obj", std::string("# a cube\no cube\n") + kCubeVertices + "vn 0 0 1\n" + kCubeFaces));
  EXPECT_EQ(m.vertices.size(), 8u);
  EXPECT_EQ(m.triangles.size(), 12u);
  EXPECT_NEAR(signed_volume(m), 1.0, 1e-12);
  EXPECT_TRUE(is_closed(m));
}

TEST(ReadObj, NegativeIndicesAndSlashForms) {
  ScratchDir dir;
  // The bottom face written after its four vertices with relative indices, the top with v/vt/vn.
  const std::string text = std::string(kCubeVertices) +
                           "f -8/1/1 -5//1 -6 -7\nf 5/1/1 6/2/1 7/3/1 8/4/1\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
  const Mesh m = read_obj(write(dir, "rel.obj", text));
  EXPECT_NEAR(signed_volume(m), 1.0, 1e-12);
  EXPECT_TRUE(is_closed(m));
}

TEST(ReadObj, ErrorsNameTheLine) {
  ScratchDir dir;
  const std::string bad_index = write(dir, "bad.obj", std::string(kCubeVertices) + "f 1 2 3\nf 1 2 9\n");
  EXPECT_EQ(message_of(bad_index, read_obj), bad_index + ":10: face index 9 outside 1..8");
  const std::string zero = write(dir, "zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
  EXPECT_NE(message_of(zero, read_obj).find("zero.obj:4: bad face index '0'"), std::string::npos);
  const std::string short_v = write(dir, "v.obj", "v 0 0\n");
  EXPECT_NE(message_of(short_v, read_obj).find("v.obj:1:"), std::string::npos);
  const std::string binary = write(dir, "bin.obj", std::string("v 0 0 0\n\x01\x02\x00\x7f garbage\n", 20));
  EXPECT_NE(message_of(binary, read_obj).find("bin.obj:2: binary data"), std::string::npos);
  const std::string empty = write(dir, "empty.obj", "# nothing\n");
  EXPECT_NE(message_of(empty, read_obj).find("no faces"), std::string::npos);
  EXPECT_NE(message_of(dir.file("missing.obj"), read_obj).find("cannot read"), std::string::npos);
  for (const std::string& m : {message_of(bad_index, read_obj), message_of(binary, read_obj)})
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
}

TEST(ReadPly, AsciiCubeWithAnExtraPropertyAndElement) {
  ScratchDir dir;
  const std::string text =
      "ply\nformat ascii 1.0\ncomment hand-written\nelement vertex 8\nproperty float x\nproperty float y\n"
      "property float z\nproperty uchar red\nelement face 6\nproperty list uchar int vertex_indices\n"
      "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n"
      "0 0 0 9\n1 0 0 9\n1 1 0 9\n0 1 0 9\n0 0 1 9\n1 0 1 9\n1 1 1 9\n0 1 1 9\n"
      "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n0 1\n";
  const Mesh m = read_ply(write(dir, "cube.ply", text));
  EXPECT_EQ(m.triangles.size(), 12u);
  EXPECT_NEAR(signed_volume(m), 1.0, 1e-12);
  EXPECT_TRUE(is_closed(m));
}

std::string binary_tetrahedron(bool truncate) {
  std::string s =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 4\nproperty list uchar int vertex_indices\nend_header\n";
  const float v[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  s.append(reinterpret_cast<const char*>(v), sizeof v);
  const std::int32_t f[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  for (const auto& t : f) {
    s.push_back(3);
    s.append(reinterpret_cast<const char*>(t), sizeof t);
  }
  if (truncate) s.resize(s.size() - 5);
  return s;
}

TEST(ReadPly, BinaryLittleEndianTetrahedron) {
  ScratchDir dir;
  const Mesh m = read_ply(write(dir, "tet.ply", binary_tetrahedron(false)));
  EXPECT_EQ(m.vertices.size(), 4u);
  EXPECT_NEAR(signed_volume(m), 1.0 / 6.0, 1e-7);
  EXPECT_TRUE(is_closed(m));
  EXPECT_NEAR(signed_volume(read_mesh(write(dir, "TET.PLY", binary_tetrahedron(false)))), 1.0 / 6.0, 1e-7);
}

TEST(ReadPly, Errors) {
  ScratchDir dir;
  const std::string cut = write(dir, "cut.ply", binary_tetrahedron(true));
  EXPECT_NE(message_of(cut, read_ply).find("ends early"), std::string::npos);
  const std::string big = write(dir, "big.ply", "ply\nformat binary_big_endian 1.0\nend_header\n");
  EXPECT_NE(message_of(big, read_ply).find("big.ply:2: format 'binary_big_endian' not supported"), std::string::npos);
  const std::string index = write(dir, "index.ply",
                                  "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                  "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                  "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n");
  EXPECT_NE(message_of(index, read_ply).find("outside 0..2"), std::string::npos);
  const std::string obj = write(dir, "not.ply", "v 0 0 0\n");
  EXPECT_NE(message_of(obj, read_ply).find("not a PLY file"), std::string::npos);
  EXPECT_THROW(read_mesh(write(dir, "mesh.stl", "solid")), MeshError);
}

TEST(WriteObj, RoundTrips) {
  ScratchDir dir;
  const Mesh cube = read_obj(write(dir, "cube.obj", std::string(kCubeVertices) + kCubeFaces));
  const Mesh back = read_obj(write(dir, "back.obj", obj_text(cube, "two\nlines")));
  ASSERT_EQ(back.vertices.size(), cube.vertices.size());
  ASSERT_EQ(back.triangles, cube.triangles);
  for (std::size_t i = 0; i < cube.vertices.size(); ++i) EXPECT_EQ(back.vertices[i], cube.vertices[i]);
}

}  // namespace
}  // namespace skylit::flight
