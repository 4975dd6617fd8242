// The viewer's camera rig and matrices (view/camera.h), against geometry worked out by
// hand: frame-rate independence of the smoothing, never below the ground (a ridge too
// thin for the sampling to see from its ends), follow and orbit placement, the
// orthographic corners, and clear rejection of bad input.
#include "view/camera.h"
#include "view/scene_view.h"

#include <gtest/gtest.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <stdexcept>

namespace {

using skylit::view::CameraInput;
using skylit::view::CameraMode;
using skylit::view::CameraPose;
using skylit::view::CameraRig;
using skylit::view::CameraTarget;
using skylit::view::RigOptions;

double flat(double, double) { return 100.0; }

// A wall 2 m thick and 500 m high across x = 1000 m (nothing else above 100 m).
double wall(double x, double) { return std::abs(x - 1000.0) < 1.0 ? 600.0 : 100.0; }

TEST(CameraRig, FollowSettlesBehindAndAboveAlongTheHeading) {
  RigOptions o;
  CameraRig rig(flat, o);
  rig.set_mode(CameraMode::Follow);
  rig.set_target({{500.0, -500.0, 400.0}, 90.0});  // flying east
  rig.settle();
  const CameraPose& p = rig.pose();
  EXPECT_NEAR(p.eye.x, 500.0 - o.follow_distance_m, 1e-9);
  EXPECT_NEAR(p.eye.y, -500.0, 1e-9);
  EXPECT_NEAR(p.eye.z, 400.0 + o.follow_height_m, 1e-9);
  const glm::dvec3 to_target = glm::normalize(glm::dvec3(500.0, -500.0, 400.0) - p.eye);
  EXPECT_NEAR(glm::dot(p.forward, to_target), 1.0, 1e-12);
  EXPECT_NEAR(glm::dot(p.forward, p.up), 0.0, 1e-12);
  EXPECT_GT(p.up.z, 0.0);
}

TEST(CameraRig, SmoothingIsFrameRateIndependent) {
  for (CameraMode mode : {CameraMode::Follow, CameraMode::Orbit}) {
    CameraRig a(flat), b(flat);
    for (CameraRig* r : {&a, &b}) {
      r->set_mode(mode);
      r->set_target({{0.0, 0.0, 300.0}, 0.0});
      r->settle();
      r->set_target({{200.0, 50.0, 350.0}, 45.0});  // a jump the rig eases toward
    }
    a.update(0.5, {});
    for (int k = 0; k < 50; ++k) b.update(0.01, {});
    EXPECT_LT(glm::distance(a.pose().eye, b.pose().eye), 1e-6);
    EXPECT_LT(glm::distance(a.pose().forward, b.pose().forward), 1e-9);
    // The eye is eased relative to the target: after 0.5 s with τ = 0.35 s, e^(−0.5/0.35)
    // of the change of the offset is left (orbit keeps its offset: none).
    CameraRig settled(flat);
    settled.set_mode(mode);
    settled.set_target({{200.0, 50.0, 350.0}, 45.0});
    settled.settle();
    CameraRig start(flat);
    start.set_mode(mode);
    start.set_target({{0.0, 0.0, 300.0}, 0.0});
    start.settle();
    const glm::dvec3 change = (settled.pose().eye - glm::dvec3(200.0, 50.0, 350.0)) - (start.pose().eye - glm::dvec3(0.0, 0.0, 300.0));
    const double gap = glm::distance(a.pose().eye, settled.pose().eye);
    if (mode == CameraMode::Orbit) {
      EXPECT_LT(glm::length(change), 1e-9);
      EXPECT_LT(gap, 1e-9);
    } else {
      EXPECT_NEAR(gap / glm::length(change), std::exp(-0.5 / 0.35), 1e-9);
    }
  }
}

TEST(CameraRig, FreeFlightNeverCrossesAThinWall) {
  CameraRig rig(wall);
  rig.set_mode(CameraMode::Free);
  rig.set_pose({{900.0, 0.0, 150.0}, {1.0, 0.0, 0.0}, {0.0, 0.0, 1.0}});
  // One long step (200 m at 80 m/s·2.5 s) from x = 900 to 1100: both ends are over 100 m
  // ground, the wall lies between them.
  CameraInput forward;
  forward.move = {0.0, 1.0, 0.0};
  rig.update(2.5, forward);
  const glm::dvec3 e = rig.pose().eye;
  EXPECT_NEAR(e.x, 1100.0, 1e-6);
  // The straight path from (900, 150) to the end must clear 603 m at x = 1000 ± 1.
  const double t = (999.0 - 900.0) / (e.x - 900.0);
  EXPECT_GE(150.0 + t * (e.z - 150.0), 603.0 - 1e-6);
}

TEST(CameraRig, NeverBelowGroundWhateverTheInput) {
  auto hills = [](double x, double y) { return 300.0 + 200.0 * std::sin(x / 150.0) * std::cos(y / 90.0); };
  CameraRig rig(hills);
  for (CameraMode mode : {CameraMode::Orbit, CameraMode::Follow, CameraMode::Free}) {
    rig.set_mode(mode);
    for (int k = 0; k < 400; ++k) {
      rig.set_target({{10.0 * k, -5.0 * k, hills(10.0 * k, -5.0 * k) + 5.0}, 3.0 * k});
      CameraInput in;
      in.move = {std::sin(0.1 * k), std::cos(0.07 * k), -1.0};
      in.pitch_rad = -0.05;
      in.zoom = k % 7 == 0 ? 3.0 : 0.0;
      in.fast = k % 3 == 0;
      rig.update(1.0 / 30.0, in);
      const glm::dvec3 e = rig.pose().eye;
      ASSERT_GE(e.z, hills(e.x, e.y) + 3.0 - 1e-6) << "mode " << camera_mode_name(mode) << " step " << k;
    }
  }
}

// Free flight starts where the orbit settles, looking at the target, and no update
// without input moves it.
TEST(CameraRig, FreeSettlesWhereTheOrbitDoes) {
  CameraRig orbit(flat), free(flat);
  free.set_mode(CameraMode::Free);
  for (CameraRig* r : {&orbit, &free}) {
    r->set_target({{500.0, -500.0, 400.0}, 90.0});
    r->settle();
  }
  EXPECT_LT(glm::distance(free.pose().eye, orbit.pose().eye), 1e-9);
  EXPECT_NEAR(glm::dot(free.pose().forward, glm::normalize(glm::dvec3(500.0, -500.0, 400.0) - free.pose().eye)), 1.0,
              1e-12);
  const CameraPose settled = free.pose();
  free.set_target({{900.0, -500.0, 400.0}, 90.0});  // the target flies on; free stays
  free.update(1.0, {});
  EXPECT_EQ(free.pose().eye, settled.eye);
  EXPECT_EQ(free.mode(), CameraMode::Free);
}

TEST(CameraRig, SwitchingModesStartsFromThePose) {
  CameraRig rig(flat);
  rig.set_mode(CameraMode::Follow);
  rig.set_target({{0.0, 0.0, 500.0}, 0.0});
  rig.settle();
  const CameraPose before = rig.pose();
  rig.set_mode(CameraMode::Orbit);
  rig.update(1.0 / 60.0, {});
  // One 1/60 s step of the blend moves the eye 1 − e^(−1/60/0.35) < 5 % of the way from
  // the follow offset to the orbit's (400 m away), not to the orbit's distance.
  const double follow_range = glm::distance(before.eye, {0.0, 0.0, 500.0});
  EXPECT_LT(glm::distance(rig.pose().eye, before.eye), 0.05 * (400.0 + follow_range));
  EXPECT_GT(glm::distance(rig.pose().eye, before.eye), 0.0);
  rig.set_mode(CameraMode::Free);
  const CameraPose orbiting = rig.pose();
  rig.update(1.0 / 60.0, {});
  EXPECT_EQ(rig.pose().eye, orbiting.eye);
}

TEST(CameraRig, OrbitPitchAndDistanceStayInTheirRanges) {
  CameraRig rig(flat);
  rig.set_target({{0.0, 0.0, 1000.0}, 0.0});
  CameraInput in;
  in.pitch_rad = 10.0;  // far past straight down
  in.zoom = 100.0;      // far past the nearest distance
  for (int k = 0; k < 200; ++k) rig.update(0.1, in);
  EXPECT_NEAR(rig.orbit_distance(), 20.0, 1e-9);
  const glm::dvec3 rel = rig.pose().eye - glm::dvec3(0.0, 0.0, 1000.0);
  EXPECT_NEAR(std::asin(rel.z / glm::length(rel)) * 180.0 / M_PI, 89.0, 0.01);
}

// With no aircraft the cameras aim at the field's centre: the overview's distances show
// the whole field (its corners, at their heights, inside the 16:9 frame) whichever way
// the orbit turns, and not as a speck (the corners span 40 % of the frame's width or
// height).
TEST(CameraRig, OverviewFramesTheWholeFieldFromEveryHeading) {
  for (const auto& [w, h] : {std::pair{327, 468}, std::pair{1024, 256}}) {
    skylit::terrain::HeightField f(w, h, 30.0);
    for (int j = 0; j < h; ++j)  // a cone 2 km high in the middle
      for (int i = 0; i < w; ++i)
        f.at(i, j) = static_cast<float>(std::max(0.0, 2000.0 - 30.0 * std::hypot(i - 0.5 * w, j - 0.5 * h)));
    const auto ground = skylit::view::ground_of(f, 1.0);
    const CameraTarget centre = skylit::view::field_centre_target(f, 1.0);
    for (CameraMode mode : {CameraMode::Orbit, CameraMode::Follow}) {
      CameraRig rig(ground, skylit::view::overview_rig_options(f, 1280.0 / 720.0, 1.0));
      rig.set_mode(mode);
      rig.set_target(centre);
      rig.settle();
      for (int step = 0; step < (mode == CameraMode::Orbit ? 24 : 1); ++step) {
        CameraInput turn;
        turn.yaw_rad = step == 0 ? 0.0 : 15.0 * M_PI / 180.0;
        rig.update(1e-3, turn);
        rig.settle();
        const skylit::view::ViewCamera c = skylit::view::perspective_camera(rig.pose(), f, 1280, 720, 1.0);
        glm::dvec2 lo(1.0), hi(-1.0);
        for (const auto& [i, j] : {std::pair{0, 0}, std::pair{w - 1, 0}, std::pair{0, h - 1}, std::pair{w - 1, h - 1}}) {
          const glm::dvec4 clip = c.proj * c.view * glm::dvec4(i * 30.0, -j * 30.0, f.at(i, j), 1.0);
          const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
          EXPECT_GT(clip.w, 0.0);
          EXPECT_LE(std::abs(ndc.x), 1.0) << w << "x" << h << " step " << step << " corner " << i << "," << j;
          EXPECT_LE(std::abs(ndc.y), 1.0) << w << "x" << h << " step " << step << " corner " << i << "," << j;
          lo = glm::min(lo, glm::dvec2(ndc));
          hi = glm::max(hi, glm::dvec2(ndc));
        }
        const glm::dvec2 span = 0.5 * (hi - lo);  // of the frame's width and height
        EXPECT_GT(std::max(span.x, span.y), 0.4) << w << "x" << h << " step " << step;
      }
    }
  }
}

TEST(Camera, OrthoNadirMapsTheExtentToTheClipSquare) {
  const glm::dmat4 m = skylit::view::ortho_nadir_matrix(-5.0, 95.0, -55.0, 5.0, 10.0, 30.0);
  auto ndc = [&](double x, double y, double z) { return glm::dvec3(m * glm::dvec4(x, y, z, 1.0)); };
  EXPECT_LT(glm::distance(ndc(-5.0, -55.0, 30.0), glm::dvec3(-1.0, -1.0, -1.0)), 1e-12);
  EXPECT_LT(glm::distance(ndc(95.0, 5.0, 10.0), glm::dvec3(1.0, 1.0, 1.0)), 1e-12);
  EXPECT_LT(glm::distance(ndc(45.0, -25.0, 20.0), glm::dvec3(0.0, 0.0, 0.0)), 1e-12);
}

TEST(Camera, NearPlaneFollowsTheNearestSurface) {
  EXPECT_DOUBLE_EQ(skylit::view::perspective_for(120.0, 1e5, 16.0 / 9.0).near_m, 60.0);
  EXPECT_DOUBLE_EQ(skylit::view::perspective_for(0.1, 1e5, 1.0).near_m, 0.5);
  EXPECT_DOUBLE_EQ(skylit::view::perspective_for(1e6, 1e7, 1.0).near_m, 1000.0);
}

TEST(Camera, BadInputIsRefused) {
  EXPECT_EQ(skylit::view::parse_camera_mode("follow"), CameraMode::Follow);
  EXPECT_EQ(skylit::view::parse_camera_mode("chase"), std::nullopt);
  EXPECT_THROW(CameraRig(nullptr), std::invalid_argument);
  RigOptions o;
  o.smoothing_s = -1.0;
  EXPECT_THROW(CameraRig(flat, o), std::invalid_argument);
  CameraRig rig(flat);
  EXPECT_THROW(rig.update(-1.0, {}), std::invalid_argument);
  EXPECT_THROW(rig.set_target({{NAN, 0.0, 0.0}, 0.0}), std::invalid_argument);
  EXPECT_THROW(rig.set_pose({{0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, {0.0, 0.0, 1.0}}), std::invalid_argument);
  EXPECT_THROW(skylit::view::ortho_nadir_matrix(1.0, 1.0, 0.0, 1.0, 0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(skylit::view::perspective_for(NAN, 1e5, 1.0), std::invalid_argument);
}

}  // namespace
