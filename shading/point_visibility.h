// Terrain onto a point above it — an aircraft's sphere centre (DESIGN.md "Aircraft"):
// sky and sun visibility by offset marching (seed 000 §4.1, "height field cast
// shadows"): the horizon march of every texel, started from the point's own height.
//
// σ_k: the largest elevation of the terrain along geographic azimuth A_k = k·2π/W seen
// from the point, Earth curvature as the march options say (negative when the point
// looks down on all of it). σ⁺ = max(σ, 0): the sky exists above the horizontal only.
//  * sky_view: (1/π)∫ V(ω) cos θ dω, a horizontal receiver at the point. A slice of
//    width 2π/W open above σ⁺ holds ∫ sin e cos e de over (σ⁺, π/2] = cos²σ⁺/2, so
//    sky_view = (1/W)·Σ cos²σ⁺_k (products.h skyview with n = z). Open sky: 1.
//  * sky_fraction: the visible share of the upper hemisphere's solid angle,
//    (1/W)·Σ (1 − sin σ⁺_k) (products.h svf).
//  * sun: σ_s marched in the sun's azimuth; the disc's visible fraction above a level
//    line at σ_s (sky/sun_disc.h); in shadow when the disc's centre is below σ_s.
// Beyond the DEM nothing is known, so the sun's horizon is floored by the sea-level
// sphere (datum height 0, radius R_eff of the march's curvature): seen from height z it
// lies at −acos(R_eff/(R_eff + z)) (0 on a flat Earth). A sun below it is night, not lit.
//
// A point off the grid has no horizons: sky 1, the sun against the floor alone, flagged.
// A point below the bilinear ground sees nothing: sky 0, sun 0, in shadow, flagged.
#pragma once

#include "shading/horizon/horizon_exact.h"
#include "shading/horizon/horizon_march.h"
#include "shading/sun_light.h"
#include "terrain/height_field.h"

#include <glm/vec3.hpp>

#include <optional>
#include <vector>

namespace skylit::shading {

struct PointVisibilityOptions {
  // W (32, the renderer's default), Earth curvature and the maximum distance of either
  // march; with dense off, also the schedule (the sun's: level 0, 32 steps per halving).
  horizon::MarchOptions march = sun_march_options();
  // The dense march (horizon_exact.h: every half texel to the DEM's edge, the project's
  // ground truth) by default: a few points can afford it, and it never skips a texel,
  // as the schedule's steps, 2^(1/k_v) apart, do beyond k_v/ln 2 ≈ 46 texels (errors
  // of both on a steep field: point_visibility_test).
  bool dense = true;
  double dense_step_texels = 0.5;
  double sun_radius = SunShadowOptions{}.radius;  // the solar disc (rad)
};

enum class PointPlace { Above, Outside, BelowGround };

struct SunVisibility {
  double horizon = 0.0;           // σ_s (rad): the terrain's or the sea-level floor's, the higher
  bool terrain_horizon = false;   // the terrain's march set σ_s (not the floor)
  double margin = 0.0;            // e_s − σ_s (rad)
  double visible_fraction = 0.0;  // of the solar disc, 0…1
  bool in_shadow = false;         // margin < 0: the disc's centre is below σ_s
};

struct PointVisibility {
  PointPlace place = PointPlace::Outside;
  std::optional<double> ground_m;  // bilinear ground height under the point (on the grid)
  std::vector<double> horizon;     // σ_k (rad), Above only; −π/2 where no step lies on the grid
  double sky_view = 1.0;
  double sky_fraction = 1.0;
  std::optional<SunVisibility> sun;  // when a sun was given
};

// Field frame (renderer.h FrameInputs: texel (i, j) at (i·dx, −j·dy)) → level-0 texels,
// the inverse of that placement (dx of the nearest row, as the renderer's spheres use).
horizon::GridPoint field_frame_texel(const terrain::HeightField& field, double x, double y);

class PointVisibilityMarcher {
 public:
  // Throws std::invalid_argument for bad march options, a dense step ≤ 0 or a radius
  // outside (0, π/4).
  explicit PointVisibilityMarcher(const terrain::HeightField& field, const PointVisibilityOptions& options = {});

  // point: field frame (x east, y north, m) and z (m, the DEM's vertical datum). Throws
  // std::invalid_argument for a non-finite point or sun, or |sun elevation| > π/2.
  PointVisibility at(const glm::dvec3& point, std::optional<SunAngles> sun = std::nullopt) const;

  const PointVisibilityOptions& options() const { return options_; }

 private:
  double march(horizon::GridPoint origin, double z, double azimuth) const;

  const terrain::HeightField& field_;
  PointVisibilityOptions options_;
  std::optional<horizon::HorizonMarcher> marcher_;  // dense off only
};

// The sea-level floor above: −acos(R_eff/(R_eff + z)) for z > 0 with curvature, else 0.
double sea_level_horizon(double z, const horizon::EarthCurvature& curvature);

}  // namespace skylit::shading
