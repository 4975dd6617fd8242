#include "view/scene_view.h"

#include <epoxy/gl.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <vector>

#include "gpu/timer.h"

namespace skylit::view {
namespace {

double field_diagonal(const terrain::HeightField& f) {
  return std::hypot(f.width * f.mean_dx(), f.height * f.dy);
}

glm::dvec2 height_range(const terrain::HeightField& f) {
  const auto [lo, hi] = std::minmax_element(f.heights.begin(), f.heights.end());
  return {*lo, *hi};
}

bool same_lighting(const std::optional<shading::Lighting>& a, const std::optional<shading::Lighting>& b) {
  if (a.has_value() != b.has_value()) return false;
  if (!a) return true;
  return a->sky == b->sky && a->sun.direction == b->sun.direction && a->sun.dni == b->sun.dni &&
         a->reference_irradiance == b->reference_irradiance;
}

}  // namespace

GroundHeight ground_of(const terrain::HeightField& field, double exaggeration) {
  const double dx = field.mean_dx(), dy = field.dy;
  return [&field, dx, dy, exaggeration](double x, double y) {
    const double fi = std::clamp(x / dx, 0.0, field.width - 1.0), fj = std::clamp(-y / dy, 0.0, field.height - 1.0);
    const int i0 = std::min(static_cast<int>(fi), field.width - 2 < 0 ? 0 : field.width - 2);
    const int j0 = std::min(static_cast<int>(fj), field.height - 2 < 0 ? 0 : field.height - 2);
    const int i1 = std::min(i0 + 1, field.width - 1), j1 = std::min(j0 + 1, field.height - 1);
    const double u = fi - i0, v = fj - j0;
    const double h = (1 - v) * ((1 - u) * field.at(i0, j0) + u * field.at(i1, j0)) +
                     v * ((1 - u) * field.at(i0, j1) + u * field.at(i1, j1));
    return h * exaggeration;
  };
}

CurvatureDrop drawn_drop(const ViewFrame& frame) {
  return curvature_drop(frame.style.curvature, frame.camera.eye, frame.camera.pixels_per_radian);
}

CameraTarget field_centre_target(const terrain::HeightField& field, double exaggeration) {
  const double x = 0.5 * (field.width - 1) * field.mean_dx(), y = -0.5 * (field.height - 1) * field.dy;
  return {{x, y, ground_of(field, exaggeration)(x, y)}, 0.0};
}

RigOptions overview_rig_options(const terrain::HeightField& field, double aspect, double exaggeration) {
  const double pitch = std::numbers::pi / 6.0;
  const double tan_v = 0.95 * std::tan(0.5 * glm::radians(kFovyDeg)), tan_h = tan_v * aspect;
  const double dx = field.mean_dx(), dy = field.dy;
  // The field's rim at its heights (at most 256 points an edge) and its highest texel.
  std::vector<glm::dvec3> rim;
  const auto add = [&](int i, int j) { rim.push_back({i * dx, -j * dy, field.at(i, j) * exaggeration}); };
  for (int k = 0; k <= 256; ++k) {
    const int i = (field.width - 1) * k / 256, j = (field.height - 1) * k / 256;
    add(i, 0);
    add(i, field.height - 1);
    add(0, j);
    add(field.width - 1, j);
  }
  const auto [low, top] = std::minmax_element(field.heights.begin(), field.heights.end());
  const auto highest = top - field.heights.begin();
  add(static_cast<int>(highest % field.width), static_cast<int>(highest / field.width));
  const double relief = (*top - *low) * exaggeration;
  const glm::dvec3 target = field_centre_target(field, exaggeration).position;
  // Whether the rim is in view from `distance` along heading `yaw`, looking at the target
  // (where the orbit puts its eye).
  const auto in_view = [&](double yaw, double distance) {
    const glm::dvec3 f = direction(yaw, -pitch);
    const glm::dvec3 eye = target - distance * f;
    const glm::dvec3 right = glm::normalize(glm::cross(f, glm::dvec3(0.0, 0.0, 1.0))), up = glm::cross(right, f);
    return std::all_of(rim.begin(), rim.end(), [&](const glm::dvec3& p) {
      const glm::dvec3 v = p - eye;
      const double depth = glm::dot(v, f);
      return depth > 0.0 && std::abs(glm::dot(v, right)) <= tan_h * depth && std::abs(glm::dot(v, up)) <= tan_v * depth;
    });
  };
  const double span = field_diagonal(field) + relief;
  double distance = 0.0;
  for (int k = 0; k < 72; ++k) {  // every 5°: the rim turns slowly with the heading
    const double yaw = k * std::numbers::pi / 36.0;
    double lo = distance, hi = std::max(distance, 1.0);
    while (!in_view(yaw, hi) && hi < 1e3 * span) hi *= 2.0;
    if (in_view(yaw, lo)) continue;
    for (int step = 0; step < 48; ++step) {
      const double mid = 0.5 * (lo + hi);
      (in_view(yaw, mid) ? hi : lo) = mid;
    }
    distance = hi;
  }
  RigOptions o;
  o.orbit_distance_m = distance;
  o.orbit_pitch_rad = pitch;
  o.follow_distance_m = distance * std::cos(pitch);
  o.follow_height_m = distance * std::sin(pitch);
  o.free_speed_mps = std::max(o.free_speed_mps, field_diagonal(field) / 60.0);
  return o;
}

ViewCamera perspective_camera(const CameraPose& pose, const terrain::HeightField& field, int width, int height,
                              double exaggeration, std::span<const blockers::Sphere> bodies, double fovy_deg) {
  const double ground = ground_of(field, exaggeration)(pose.eye.x, pose.eye.y);
  const double extent = 4.0 * field_diagonal(field) + std::max(0.0, pose.eye.z - ground);
  double nearest = pose.eye.z - ground;
  for (const blockers::Sphere& s : bodies)
    nearest = std::min(nearest, glm::distance(pose.eye, s.centre * glm::dvec3(1.0, 1.0, exaggeration)) - s.radius);
  const Perspective p = perspective_for(nearest, extent, static_cast<double>(width) / height, fovy_deg);
  ViewCamera c;
  c.view = view_matrix(pose);
  c.proj = projection_matrix(p);
  c.eye = pose.eye;
  c.pixels_per_radian = height / (2.0 * std::tan(0.5 * glm::radians(p.fovy_deg)));
  return c;
}

ViewCamera ortho_nadir_camera(const terrain::HeightField& field, double exaggeration) {
  const double dx = field.mean_dx(), dy = field.dy;
  const glm::dvec2 r = height_range(field) * exaggeration;
  ViewCamera c;
  c.proj = ortho_nadir_matrix(-0.5 * dx, (field.width - 0.5) * dx, -(field.height - 0.5) * dy, 0.5 * dy,
                              r.x - 10.0, r.y + 10.0);
  c.eye = {0.5 * (field.width - 1) * dx, -0.5 * (field.height - 1) * dy, r.y + 10.0};
  return c;
}

SceneView::SceneView(gpu::GpuRenderer& renderer, const terrain::HeightField& field,
                     const shading::ProductOptions& options, bool aircraft)
    : renderer_(renderer), field_(field), terrain_(field) {
  renderer_.set_field(field);
  renderer_.set_options(options);
  renderer_.expect_frames(2);  // many frames: keep the visibility between them
  renderer_.expect_blockers(aircraft);
  renderer_.set_sun_heading_tolerance(kSunTolerance);
  renderer_.keep_sky_irradiance(true);
}

ViewTimings SceneView::draw(const ViewFrame& frame, int width, int height, bool measure) {
  ViewTimings t;
  const auto start = std::chrono::steady_clock::now();
  auto lap = [&, last = start]() mutable {
    if (measure) glFinish();
    const auto now = std::chrono::steady_clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - last).count();
    last = now;
    return ms;
  };
  if (!frame.reuse_shading || !shaded_) {
    shaded_.reset();
    shaded_.emplace(renderer_.frame_on_gpu(shading::Product::Shaded, frame.shading));
  }
  terrain_.set_colour(*shaded_, frame.style.tone);
  const gpu::GpuFrame& shaded = *shaded_;
  t.horizons_reused = frame.reuse_shading || renderer_.last_timings().horizons_reused;
  t.stale_texels = renderer_.last_timings().stale_texels;
  t.sun_far_reused = frame.reuse_shading || renderer_.last_timings().sun_far_reused;
  t.shading_kept = frame.reuse_shading || renderer_.last_timings().shading_kept;
  t.texels = field_.size();
  terrain_.sync(field_);
  t.shading_ms = lap();

  const bool perspective = frame.camera.pixels_per_radian > 0.0;
  const bool srgb = frame.style.tone == shading::ToneCurve::Srgb;
  const glm::dmat4 view_proj = frame.camera.proj * frame.camera.view;
  glViewport(0, 0, width, height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);
  glClearColor(static_cast<float>(frame.clear.r), static_cast<float>(frame.clear.g), static_cast<float>(frame.clear.b), 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  terrain_.draw(view_proj, frame.camera.eye, frame.camera.pixels_per_radian, frame.style);
  t.terrain_nodes = terrain_.last_node_count();
  t.terrain_ms = lap();
  // After the terrain: the sky, at the far plane, is shaded only where no ground is.
  if (perspective) {
    if (!baked_ || !same_lighting(baked_for_, frame.shading.lighting) || baked_scale_ != shaded.display_scale ||
        baked_tone_ != frame.style.tone) {
      baked_ = bake_sky(frame.shading.lighting, shaded.display_scale);
      baked_for_ = frame.shading.lighting;
      baked_scale_ = shaded.display_scale;
      baked_tone_ = frame.style.tone;
      sky_.set(*baked_, baked_tone_);
    }
    sky_.draw(view_proj);
  }
  t.sky_ms = lap();
  if (frame.draw_bodies && perspective && baked_)
    spheres_.draw(frame.shading.spheres, frame.camera.view, frame.camera.proj, frame.style.exaggeration,
                  drawn_drop(frame), sky_.light(), srgb);
  t.bodies_ms = lap();
  t.total_ms = gpu::ms_since(start);
  return t;
}

}  // namespace skylit::view
