// One frame of the viewer, the same for the window and headless `render`: the renderer's
// `shaded` frame (sun, sky and aircraft per frame; horizons kept while the field and
// options stay) left on the GPU, then the sky, the terrain coloured by that frame, and
// the aircraft bodies, drawn into the bound framebuffer of the renderer's context.
#pragma once

#include <glm/mat4x4.hpp>

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "gpu/gpu_renderer.h"
#include "shading/renderer.h"
#include "terrain/height_field.h"
#include "view/camera.h"
#include "view/sky_draw.h"
#include "view/sphere_draw.h"
#include "view/terrain_draw.h"

namespace skylit::view {

// Where the frame is seen from.
struct ViewCamera {
  glm::dmat4 view{1.0}, proj{1.0};
  glm::dvec3 eye{0.0};
  double pixels_per_radian = 0.0;  // 0: orthographic
};

// The cameras' vertical field of view (degrees).
inline constexpr double kFovyDeg = 50.0;

// A perspective camera at `pose` for a viewport of width × height; its near plane stays
// in front of the ground and of `bodies` (the frame's aircraft, drawn z × exaggeration).
ViewCamera perspective_camera(const CameraPose& pose, const terrain::HeightField& field, int width, int height,
                              double exaggeration, std::span<const blockers::Sphere> bodies = {},
                              double fovy_deg = kFovyDeg);
// Straight down over the field's extent (texel centres ± half a texel): pixel (c, r) of
// a field-sized viewport is texel (c, r).
ViewCamera ortho_nadir_camera(const terrain::HeightField& field, double exaggeration);

// Ground height (exaggerated) at field-frame (x, y), bilinear in the heights, clamped to
// the edges: what keeps cameras above the ground.
GroundHeight ground_of(const terrain::HeightField& field, double exaggeration);

// The field's centre on its (exaggerated) ground, heading north: what the cameras aim
// at with no aircraft to follow.
CameraTarget field_centre_target(const terrain::HeightField& field, double exaggeration);

// The rig's distances when it aims at the field's centre (no aircraft to follow): the
// follow and orbit eyes the least distance, 30° over the centre, from which the field's
// rim (its edges at their heights, × exaggeration) and its highest texel fill at most
// 95 % of a kFovyDeg view of this aspect (width / height) from every heading the orbit
// may take. Free flight crosses the field in a minute (at least the
// aircraft's 80 m/s).
RigOptions overview_rig_options(const terrain::HeightField& field, double aspect, double exaggeration);

// How far the sun may move before the frame's sun slopes (GpuRenderer::
// set_sun_heading_tolerance) and lighting (LightingReuse, view/lighting_reuse.h) are
// made again.
inline constexpr double kSunTolerance = shading::kFrameSunTolerance;
// How far the sun may move from where the sky model was made before it is made again:
// the sky's radiance follows the sun slowly (at 0.5° a texel's irradiance moves by
// under 1e-3 of the brightest one: view_lighting_reuse_test), and remaking it (its
// tables and each texel's sky irradiance) cost as much as sweeping the sun's slopes.
inline constexpr double kSkyTolerance = 10.0 * kSunTolerance;

struct ViewFrame {
  shading::FrameInputs shading;  // the sun and sky, the aircraft's spheres, exposure
  ViewCamera camera;
  TerrainStyle style;
  bool draw_bodies = true;  // the aircraft drawn (the top-down map shows their shadows only)
  glm::dvec3 clear{0.0};    // behind everything where no sky is drawn (orthographic)
  // Draws the renderer's previous frame again (the tiles of one screenshot), if any.
  bool reuse_shading = false;
};

// How far the frame's ground falls from its eye (Earth's curvature): what is drawn over
// the ground falls by the same.
CurvatureDrop drawn_drop(const ViewFrame& frame);

// Where a frame's time went (wall clock, ms; with `measure`, each pass is finished
// before the next starts).
struct ViewTimings {
  double shading_ms = 0.0;  // the renderer's frame (horizons, when not kept, the sun, the spheres)
  double sky_ms = 0.0, terrain_ms = 0.0, bodies_ms = 0.0, total_ms = 0.0;
  std::size_t terrain_nodes = 0;
  bool horizons_reused = false;
  // Texels whose shading still waits for the refresh after a terrain edit (the
  // renderer's FrameTimings::stale_texels), of `texels`.
  std::size_t stale_texels = 0, texels = 0;
  bool sun_far_reused = false;  // the sun's far slopes were an earlier frame's (kSunHeadingTolerance)
  // The lighting was the last frame's (LightingReuse): only what the aircraft change was shaded.
  bool shading_kept = false;
};

class SceneView {
 public:
  // The renderer's field must stay alive and resident (renderer.set_field) while the view
  // draws; `options` are the renderer's (the `shaded` product's horizon and quality).
  // `aircraft`: frames may carry spheres (Renderer::expect_blockers), so a frame without
  // any (a track's gap) keeps the horizons.
  SceneView(gpu::GpuRenderer& renderer, const terrain::HeightField& field, const shading::ProductOptions& options,
            bool aircraft);

  // Draws into the framebuffer bound now (viewport width × height).
  ViewTimings draw(const ViewFrame& frame, int width, int height, bool measure = false);

 private:
  gpu::GpuRenderer& renderer_;
  const terrain::HeightField& field_;
  TerrainDraw terrain_;
  SkyDraw sky_;
  SphereDraw spheres_;
  std::optional<gpu::GpuFrame> shaded_;  // the last frame's (valid until the renderer's next)
  std::optional<SkyMap> baked_;  // for the lighting below
  std::optional<shading::Lighting> baked_for_;
  double baked_scale_ = 0.0;
  shading::ToneCurve baked_tone_ = shading::ToneCurve::Srgb;
};

}  // namespace skylit::view
