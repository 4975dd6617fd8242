// The viewer's cameras (pure CPU math): a rig that follows or orbits a target (an
// aircraft, the DEM centre) or flies freely, never below the ground, and the GL matrices
// (clip depth −1..1) for perspective views and the straight-down orthographic render.
// Field frame: x east, y north, z up, metres; texel (i, j) of the height field is at
// (i·dx, −j·dy).
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <functional>
#include <optional>
#include <string_view>

namespace skylit::view {

struct CameraPose {
  glm::dvec3 eye{0.0};
  glm::dvec3 forward{0, 1, 0};  // unit
  glm::dvec3 up{0, 0, 1};       // unit, orthogonal to forward
};

// The unit direction of a heading (rad clockwise from north) and an elevation (rad up):
// where the orbit's eye lies from its target, reversed (−distance · direction(yaw, −pitch)).
glm::dvec3 direction(double yaw, double pitch);

// Ground height (m) at field-frame (x, y): the caller samples the height field
// (bilinear); outside the field it returns the nearest edge's height. NaN: no ground.
using GroundHeight = std::function<double(double x, double y)>;

enum class CameraMode { Follow, Orbit, Free };
std::optional<CameraMode> parse_camera_mode(std::string_view name);  // "follow" | "orbit" | "free"
std::string_view camera_mode_name(CameraMode mode);

// What the camera follows or orbits: a point and a heading (degrees clockwise from
// north), e.g. a flight::Pose's position and attitude.heading_deg, or the DEM centre.
struct CameraTarget {
  glm::dvec3 position{0.0};
  double heading_deg = 0.0;
};

// Per-frame user input (all zero: none). move: (right, forward, up), each in [−1, 1]
// (WASD, Q/E). yaw_rad: turns the view clockwise seen from above; pitch_rad: tilts the
// view up in free mode, raises the eye over the target in orbit (mouse deltas, not
// rates). zoom: wheel steps (+ closer in follow/orbit, faster in free). fast: Shift.
struct CameraInput {
  glm::dvec3 move{0.0};
  double yaw_rad = 0.0, pitch_rad = 0.0;
  double zoom = 0.0;
  bool fast = false;
};

struct RigOptions {
  double min_clearance_m = 3.0;
  double follow_distance_m = 120.0;
  double follow_height_m = 35.0;
  double orbit_distance_m = 400.0;
  double orbit_pitch_rad = 0.5;  // the orbit eye's first elevation over the target
  double free_speed_mps = 80.0;
  double smoothing_s = 0.35;  // time constant of the exponential smoothing; 0: none
};

// The ground is checked along each move at samples at most this far apart horizontally
// (up to kMaxGroundSamples per move; longer moves sample coarser).
inline constexpr double kGroundSampleStepM = 1.0;
inline constexpr int kMaxGroundSamples = 1 << 16;

// Follow: eye behind the target along its heading by follow_distance_m and above by
// follow_height_m, looking at it (zoom scales both, ×0.85 a step). Orbit: around the
// target at orbit_distance_m (×0.85 a zoom step, 20 m … 200 km), world-fixed yaw,
// eye elevation in [−5°, 89°]. Both smooth the eye and the look-at point relative to the
// target, so a target at constant velocity is tracked without lag. Free: WASD/QE move in
// the view's frame at free_speed_mps (×5 fast, ×1.25 a zoom step), mouse look with the
// pitch in ±89°; not smoothed.
// Never below ground: after every update and set_pose the eye is at least
// min_clearance_m above ground(eye.xy), and so is the straight segment from the previous
// eye (sampled every kGroundSampleStepM, each sample against the ground at it and its
// neighbours, so a wall between samples is not missed; the first step from the previous
// eye is the resolution): where it would cross the ground the new eye is lifted.
class CameraRig {
 public:
  explicit CameraRig(GroundHeight ground, RigOptions options = {});  // starts in Orbit

  // Keeps the current pose as the start and blends from it; free mode starts at it.
  void set_mode(CameraMode mode);
  CameraMode mode() const { return mode_; }
  void set_target(const CameraTarget& target);  // per frame, before update
  const CameraTarget& target() const { return target_; }

  // Advances by dt seconds (>= 0; 0 keeps the pose and ignores the input). Frame-rate
  // independent: the smoothing factor is 1 − exp(−dt/τ), so N updates of dt/N land where
  // one of dt does for a constant target.
  void update(double dt_s, const CameraInput& input);

  // A cut to where a long update settles for the current target (follow, orbit; free
  // mode cuts to where the orbit settles, looking at the target, and flies from there):
  // only the end is lifted above ground, nothing sweeps between.
  void settle();

  const CameraPose& pose() const { return pose_; }
  void set_pose(const CameraPose& pose);  // teleport (no blending), clamped above ground

  double orbit_distance() const { return orbit_distance_; }
  double free_speed() const;  // m/s without fast

 private:
  double required_z(double x, double y) const;  // ground + clearance; −inf where no ground
  glm::dvec3 clear_move(glm::dvec3 from, glm::dvec3 to) const;
  void aim(const glm::dvec3& eye, const glm::dvec3& forward);
  void update_free(double dt_s, const CameraInput& input);
  void update_tracking(double dt_s, const CameraInput& input);
  glm::dvec3 wanted_offset(const CameraInput& input);  // eye − target where tracking settles

  GroundHeight ground_;
  RigOptions options_;
  CameraMode mode_ = CameraMode::Orbit;
  CameraTarget target_;
  CameraPose pose_;
  bool restart_blend_ = true;        // take the blend's start from the pose at the next update
  glm::dvec3 eye_rel_{0.0};          // eye − target
  glm::dvec3 focus_rel_{0.0};        // look-at point − target
  double follow_scale_ = 1.0;        // follow distance and height scale (zoom)
  double orbit_yaw_ = 0.0;           // the view's heading (rad clockwise from north)
  double orbit_pitch_ = 0.5;         // the eye's elevation over the target (rad; RigOptions' first)
  double orbit_distance_ = 400.0;
  double speed_steps_ = 0.0;         // free speed zoom steps
};

// GL view matrix: eye to the origin, forward to −z, up to +y.
glm::dmat4 view_matrix(const CameraPose& pose);

// Perspective with a vertical field of view (degrees). perspective_for picks near from
// the distance to the nearest drawn surface (the eye's height above ground, or less where
// an aircraft is closer), clamp(0.5·nearest, 0.5, 1000) m, so depth precision holds from
// 100 m over the ground to a view of the whole DEM; far is the scene extent (e.g. 4× the
// DEM diagonal plus altitude).
struct Perspective {
  double fovy_deg = 50.0;
  double aspect = 16.0 / 9.0;
  double near_m = 1.0;
  double far_m = 1e5;
};
Perspective perspective_for(double nearest_m, double scene_extent_m, double aspect, double fovy_deg = 50.0);
glm::dmat4 projection_matrix(const Perspective& p);

// Straight down over the field rectangle [x0, x1] × [y0, y1] (the DEM's extent: texel
// centres ± half a texel), heights [z_lo, z_hi]: view-projection with NDC x −1 at x0 and
// +1 at x1, NDC y −1 at y0 and +1 at y1 (north: the top row once a read-back is flipped
// top-down), z_hi at depth −1 and z_lo at +1. Pixel centres of a framebuffer with one
// pixel per texel land on the texel centres.
glm::dmat4 ortho_nadir_matrix(double x0, double x1, double y0, double y1, double z_lo, double z_hi);

}  // namespace skylit::view
