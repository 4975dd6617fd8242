#include "view/camera.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace skylit::view {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr double kZoomFactor = 0.85;  // distance per zoom step
constexpr double kMinDistance = 20.0, kMaxDistance = 2e5;
constexpr double kSpeedStep = 1.25, kMaxSpeedSteps = 30.0, kFastFactor = 5.0;
const glm::dvec3 kUp(0, 0, 1);

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

glm::dvec3 direction(double yaw, double pitch) {
  return {std::sin(yaw) * std::cos(pitch), std::cos(yaw) * std::cos(pitch), std::sin(pitch)};
}

std::optional<CameraMode> parse_camera_mode(std::string_view name) {
  if (name == "follow") return CameraMode::Follow;
  if (name == "orbit") return CameraMode::Orbit;
  if (name == "free") return CameraMode::Free;
  return std::nullopt;
}

std::string_view camera_mode_name(CameraMode mode) {
  switch (mode) {
    case CameraMode::Follow: return "follow";
    case CameraMode::Orbit: return "orbit";
    case CameraMode::Free: return "free";
  }
  return "?";
}

CameraRig::CameraRig(GroundHeight ground, RigOptions options) : ground_(std::move(ground)), options_(options) {
  if (!ground_) throw std::invalid_argument("camera rig: no ground height function");
  const RigOptions& o = options_;
  if (!(o.min_clearance_m >= 0.0 && std::isfinite(o.min_clearance_m)))
    throw std::invalid_argument("camera rig: min_clearance_m must be finite and >= 0");
  if (!(o.follow_distance_m > 0.0 && std::isfinite(o.follow_distance_m) && std::isfinite(o.follow_height_m)))
    throw std::invalid_argument("camera rig: follow_distance_m must be > 0 and follow_height_m finite");
  if (!(o.orbit_distance_m > 0.0 && std::isfinite(o.orbit_distance_m)))
    throw std::invalid_argument("camera rig: orbit_distance_m must be finite and > 0");
  if (!(o.free_speed_mps > 0.0 && std::isfinite(o.free_speed_mps)))
    throw std::invalid_argument("camera rig: free_speed_mps must be finite and > 0");
  if (!(o.smoothing_s >= 0.0 && std::isfinite(o.smoothing_s)))
    throw std::invalid_argument("camera rig: smoothing_s must be finite and >= 0");
  if (!(std::abs(o.orbit_pitch_rad) < 1.5))
    throw std::invalid_argument("camera rig: orbit_pitch_rad must be within ±1.5");
  orbit_distance_ = std::clamp(o.orbit_distance_m, kMinDistance, kMaxDistance);
  orbit_pitch_ = std::clamp(o.orbit_pitch_rad, -5.0 * kDeg, 89.0 * kDeg);
  pose_.eye.z = std::max(pose_.eye.z, required_z(pose_.eye.x, pose_.eye.y));
}

void CameraRig::set_mode(CameraMode mode) {
  if (mode == mode_) return;
  mode_ = mode;
  restart_blend_ = true;
}

void CameraRig::set_target(const CameraTarget& target) {
  if (!finite(target.position) || !std::isfinite(target.heading_deg))
    throw std::invalid_argument("camera rig: target position and heading must be finite");
  target_ = target;
}

void CameraRig::set_pose(const CameraPose& pose) {
  const glm::dvec3 f = glm::normalize(pose.forward);
  const glm::dvec3 up = pose.up - f * glm::dot(pose.up, f);
  if (!finite(pose.eye) || !finite(f) || !(glm::length(up) > 1e-9))
    throw std::invalid_argument("camera rig: pose needs a finite eye and non-parallel forward and up");
  pose_ = {pose.eye, f, glm::normalize(up)};
  pose_.eye.z = std::max(pose_.eye.z, required_z(pose_.eye.x, pose_.eye.y));
  restart_blend_ = true;
}

double CameraRig::free_speed() const { return options_.free_speed_mps * std::pow(kSpeedStep, speed_steps_); }

double CameraRig::required_z(double x, double y) const {
  const double g = ground_(x, y);
  return std::isnan(g) ? -kInf : g + options_.min_clearance_m;
}

// The straight segment from `from` to `to` at samples t_k = k/n: the segment's height at
// t_k must clear the ground at t_{k−1}, t_k and t_{k+1}, so (being linear) it clears
// a wall that rises between two samples. Raising only the end keeps earlier samples
// cleared (the segment's height at t grows with the end's), so one pass suffices.
glm::dvec3 CameraRig::clear_move(glm::dvec3 from, glm::dvec3 to) const {
  from.z = std::max(from.z, required_z(from.x, from.y));  // the ground may have been edited
  const glm::dvec2 d(to.x - from.x, to.y - from.y);
  const double steps = std::ceil(glm::length(d) / kGroundSampleStepM);
  const int n = static_cast<int>(std::clamp(steps, 1.0, static_cast<double>(kMaxGroundSamples)));
  const auto req = [&](int k) {
    const double t = static_cast<double>(k) / n;
    return required_z(from.x + t * d.x, from.y + t * d.y);
  };
  double r0 = req(0), r1 = req(1);
  for (int k = 1; k <= n; ++k) {
    const double r2 = k < n ? req(k + 1) : -kInf;
    const double need = std::max({r0, r1, r2});
    const double t = static_cast<double>(k) / n;
    if (from.z + t * (to.z - from.z) < need) to.z = from.z + (need - from.z) / t;
    r0 = r1;
    r1 = r2;
  }
  return to;
}

// Roll-free orientation: right horizontal; looking straight up or down keeps the last right.
void CameraRig::aim(const glm::dvec3& eye, const glm::dvec3& forward) {
  const glm::dvec3 f = glm::normalize(forward);
  glm::dvec3 right = glm::cross(f, kUp);
  if (glm::length(right) < 1e-9) {
    right = glm::cross(pose_.forward, pose_.up);
    right -= f * glm::dot(right, f);
  }
  right = glm::normalize(right);
  pose_ = {eye, f, glm::cross(right, f)};
}

void CameraRig::update(double dt_s, const CameraInput& input) {
  if (!(dt_s >= 0.0 && std::isfinite(dt_s))) throw std::invalid_argument("camera rig: dt must be finite and >= 0");
  if (!finite(input.move) || !std::isfinite(input.yaw_rad) || !std::isfinite(input.pitch_rad) ||
      !std::isfinite(input.zoom))
    throw std::invalid_argument("camera rig: input must be finite");
  if (dt_s == 0.0) return;
  if (mode_ == CameraMode::Free) {
    update_free(dt_s, input);
  } else {
    update_tracking(dt_s, input);
  }
}

void CameraRig::update_free(double dt_s, const CameraInput& input) {
  restart_blend_ = false;
  speed_steps_ = std::clamp(speed_steps_ + input.zoom, -kMaxSpeedSteps, kMaxSpeedSteps);
  glm::dvec3 f = pose_.forward;
  if (input.yaw_rad != 0.0 || input.pitch_rad != 0.0) {
    // Heading from the view; straight down (up) the heading is where up (down) points.
    glm::dvec2 h(f.x, f.y);
    if (glm::length(h) < 1e-9) h = glm::dvec2(pose_.up.x, pose_.up.y) * (f.z < 0.0 ? 1.0 : -1.0);
    const double yaw = std::atan2(h.x, h.y) + input.yaw_rad;
    const double pitch = std::clamp(std::asin(std::clamp(f.z, -1.0, 1.0)) + input.pitch_rad, -89.0 * kDeg, 89.0 * kDeg);
    f = direction(yaw, pitch);
    aim(pose_.eye, f);
  }
  const glm::dvec3 m = glm::clamp(input.move, -1.0, 1.0);
  if (m == glm::dvec3(0.0)) return;
  const double speed = free_speed() * (input.fast ? kFastFactor : 1.0);
  const glm::dvec3 right = glm::cross(pose_.forward, pose_.up);
  const glm::dvec3 v = speed * (m.x * right + m.y * pose_.forward + m.z * pose_.up);
  aim(clear_move(pose_.eye, pose_.eye + v * dt_s), pose_.forward);
}

void CameraRig::update_tracking(double dt_s, const CameraInput& input) {
  const glm::dvec3 target = target_.position;
  if (restart_blend_) {
    // Start from the pose: the eye where it is, the look-at point ahead on its forward.
    eye_rel_ = pose_.eye - target;
    const double dist = std::max(glm::length(eye_rel_), 1.0);
    focus_rel_ = eye_rel_ + pose_.forward * dist;
    if (mode_ == CameraMode::Orbit && glm::length(eye_rel_) > 0.0) {  // swing in from where the eye is
      if (glm::length(glm::dvec2(eye_rel_)) > 1e-9) orbit_yaw_ = std::atan2(-eye_rel_.x, -eye_rel_.y);
      orbit_pitch_ = std::clamp(std::asin(eye_rel_.z / glm::length(eye_rel_)), -5.0 * kDeg, 89.0 * kDeg);
    }
    restart_blend_ = false;
  }
  const glm::dvec3 want = wanted_offset(input);
  // Exact exponential smoothing, so the result does not depend on how dt is split.
  const double a = options_.smoothing_s > 0.0 ? -std::expm1(-dt_s / options_.smoothing_s) : 1.0;
  eye_rel_ += (want - eye_rel_) * a;
  focus_rel_ -= focus_rel_ * a;
  const glm::dvec3 wanted_eye = target + eye_rel_;
  const glm::dvec3 eye = clear_move(pose_.eye, wanted_eye);
  if (eye != wanted_eye) eye_rel_ = eye - target;
  const glm::dvec3 look = target + focus_rel_ - eye;
  aim(eye, glm::length(look) > 1e-9 ? look : pose_.forward);
}

glm::dvec3 CameraRig::wanted_offset(const CameraInput& input) {
  const double zoom = std::pow(kZoomFactor, input.zoom);
  glm::dvec3 want;
  if (mode_ == CameraMode::Follow) {
    const double base = options_.follow_distance_m;
    follow_scale_ = std::clamp(follow_scale_ * zoom, std::min(1.0, kMinDistance / base), std::max(1.0, kMaxDistance / base));
    const double heading = target_.heading_deg * kDeg;
    want = follow_scale_ * (glm::dvec3(-base * std::sin(heading), -base * std::cos(heading), options_.follow_height_m));
  } else {
    orbit_distance_ = std::clamp(orbit_distance_ * zoom, kMinDistance, kMaxDistance);
    orbit_yaw_ = std::remainder(orbit_yaw_ + input.yaw_rad, 2.0 * 3.14159265358979323846);
    orbit_pitch_ = std::clamp(orbit_pitch_ + input.pitch_rad, -5.0 * kDeg, 89.0 * kDeg);
    want = -orbit_distance_ * direction(orbit_yaw_, -orbit_pitch_);
  }
  return want;
}

void CameraRig::settle() {
  if (mode_ == CameraMode::Free) {  // free flight starts where the orbit settles
    mode_ = CameraMode::Orbit;
    settle();
    mode_ = CameraMode::Free;
    return;
  }
  restart_blend_ = false;
  eye_rel_ = wanted_offset({});
  focus_rel_ = glm::dvec3(0.0);
  glm::dvec3 eye = target_.position + eye_rel_;
  eye.z = std::max(eye.z, required_z(eye.x, eye.y));
  eye_rel_ = eye - target_.position;
  const glm::dvec3 look = target_.position - eye;
  aim(eye, glm::length(look) > 1e-9 ? look : pose_.forward);
}

glm::dmat4 view_matrix(const CameraPose& pose) {
  if (!finite(pose.eye) || !(glm::length(glm::cross(pose.forward, pose.up)) > 1e-12))
    throw std::invalid_argument("view_matrix: needs a finite eye and non-parallel forward and up");
  return glm::lookAtRH(pose.eye, pose.eye + pose.forward, pose.up);
}

Perspective perspective_for(double nearest_m, double scene_extent_m, double aspect, double fovy_deg) {
  if (std::isnan(nearest_m)) throw std::invalid_argument("perspective_for: the nearest distance is NaN");
  const double near = std::clamp(0.5 * nearest_m, 0.5, 1000.0);
  if (!(scene_extent_m > near && std::isfinite(scene_extent_m)))
    throw std::invalid_argument("perspective_for: scene extent must be finite and beyond the near plane");
  Perspective p{fovy_deg, aspect, near, scene_extent_m};
  projection_matrix(p);  // validates fovy and aspect
  return p;
}

glm::dmat4 projection_matrix(const Perspective& p) {
  if (!(p.fovy_deg > 0.0 && p.fovy_deg < 180.0)) throw std::invalid_argument("projection: fovy must be in (0, 180) degrees");
  if (!(p.aspect > 0.0 && std::isfinite(p.aspect))) throw std::invalid_argument("projection: aspect must be finite and > 0");
  if (!(p.near_m > 0.0 && p.far_m > p.near_m && std::isfinite(p.far_m)))
    throw std::invalid_argument("projection: needs 0 < near < far < inf");
  return glm::perspectiveRH_NO(p.fovy_deg * kDeg, p.aspect, p.near_m, p.far_m);
}

// The eye at the origin looking down −z with north up is the identity view, so the
// projection alone is the view-projection: view z = field z, near −z_hi, far −z_lo.
glm::dmat4 ortho_nadir_matrix(double x0, double x1, double y0, double y1, double z_lo, double z_hi) {
  if (!(x1 > x0 && y1 > y0 && z_hi > z_lo) || !std::isfinite(x1 - x0) || !std::isfinite(y1 - y0) ||
      !std::isfinite(z_hi - z_lo))
    throw std::invalid_argument("ortho_nadir_matrix: needs finite x0 < x1, y0 < y1, z_lo < z_hi");
  return glm::orthoRH_NO(x0, x1, y0, y1, -z_hi, -z_lo);
}

}  // namespace skylit::view
