// Mesh geometry against closed forms: volumes of a box, an n-gon prism and an
// icosahedron; closedness; the winding-number inside test, also for overlapping shells.
#include "flight/mesh.h"
#include "flight/mesh_inside.h"
#include "flight/mesh_shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace skylit::flight {
namespace {

TEST(MeshVolume, BoxIsTheProductOfItsSides) {
  const Mesh box = make_box({-1, -2, 0.5}, {2, 1.5, 1.25});
  EXPECT_NEAR(signed_volume(box), 3.0 * 3.5 * 0.75, 1e-12);
  EXPECT_TRUE(is_closed(box));
}

TEST(MeshVolume, PrismIsItsPolygonAreaTimesHeight) {
  // A regular n-gon of circumradius r has area n/2 · r² · sin(2π/n).
  for (int n : {3, 7, 64}) {
    const Mesh p = make_prism(1.5, 2.0, n);
    EXPECT_NEAR(signed_volume(p), n / 2.0 * 1.5 * 1.5 * std::sin(2 * std::numbers::pi / n) * 2.0, 1e-12) << n;
    EXPECT_TRUE(is_closed(p));
  }
}

TEST(MeshVolume, IcosahedronAndIcosphere) {
  // Icosahedron of circumradius R: edge a = R / sin(2π/5), volume 5/12 (3 + √5) a³.
  const double r = 2.0, a = r / std::sin(2 * std::numbers::pi / 5);
  EXPECT_NEAR(signed_volume(make_icosphere(r, 0)), 5.0 / 12.0 * (3 + std::sqrt(5.0)) * a * a * a, 1e-12);
  // Subdivided, it is inscribed in the ball: below 4/3 π R³ and approaching it.
  const double ball = 4.0 / 3.0 * std::numbers::pi * r * r * r;
  const double v3 = signed_volume(make_icosphere(r, 3)), v4 = signed_volume(make_icosphere(r, 4));
  EXPECT_LT(v3, v4);
  EXPECT_LT(v4, ball);
  EXPECT_GT(v4, 0.995 * ball);
  EXPECT_TRUE(is_closed(make_icosphere(r, 3)));
}

TEST(MeshClosed, AMissingOrFlippedTriangleOpensIt) {
  Mesh box = make_box({0, 0, 0}, {1, 1, 1});
  Mesh open = box;
  open.triangles.pop_back();
  EXPECT_FALSE(is_closed(open));
  EXPECT_THROW(check_closed_mesh(open, "box"), MeshError);
  Mesh flipped = box;
  std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
  EXPECT_FALSE(is_closed(flipped));
  EXPECT_THROW(check_closed_mesh(Mesh{}, "empty"), MeshError);
  Mesh bad_index = box;
  bad_index.triangles[0][0] = 999;
  EXPECT_THROW(check_closed_mesh(bad_index, "bad"), MeshError);
  EXPECT_NO_THROW(check_closed_mesh(box, "box"));
}

TEST(MeshInsideTest, PointsOfABoxAndOfTwoOverlappingBoxes) {
  const Mesh box = make_box({0, 0, 0}, {2, 1, 1});
  const MeshInside inside(box);
  EXPECT_TRUE(inside({1.0, 0.5, 0.5}));
  EXPECT_TRUE(inside({1.9, 0.1, 0.9}));
  EXPECT_FALSE(inside({2.1, 0.5, 0.5}));
  EXPECT_FALSE(inside({1.0, 0.5, -0.1}));
  EXPECT_FALSE(inside({1.0, 0.5, 1.1}));

  // Two unit cubes overlapping in [0.5, 1] along x: winding 2 there, union 1.5 m³.
  Mesh two = make_box({0, 0, 0}, {1, 1, 1});
  two.append(make_box({0.5, 0, 0}, {1.5, 1, 1}));
  const MeshInside in_two(two);
  EXPECT_EQ(in_two.winding_number({0.75, 0.5, 0.5}), 2);
  EXPECT_EQ(in_two.winding_number({0.25, 0.5, 0.5}), 1);
  EXPECT_EQ(in_two.winding_number({1.6, 0.5, 0.5}), 0);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int hits = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) hits += in_two({2.0 * u(rng), u(rng), u(rng)});
  const double p = 0.75;  // 1.5 m³ of the 2 m³ box
  EXPECT_NEAR(static_cast<double>(hits) / n, p, 4 * std::sqrt(p * (1 - p) / n));
}

}  // namespace
}  // namespace skylit::flight
