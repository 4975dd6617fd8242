// The frames' lighting, kept while the sun moves little. Each frame resolves its lighting
// at its own time, and LightingReuse hands back
//  * the last frame's lighting whole while the sun stays within kSunTolerance of it and
//    its DNI and the tone map's reference within kLightingRelativeTolerance: the renderer
//    then shades again only the texels the aircraft change (GpuRenderer's partial frames);
//  * else the frame's own sun and tone map with the sky model of an earlier frame, while
//    the sun has moved less than the sky's angle (kSkyTolerance) since that model was
//    made: the renderer keeps the sky's tables and each texel's sky irradiance
//    (GpuRenderer::keep_sky_irradiance);
//  * else the frame's own lighting, whose sky model is kept from then on.
// The request must be the same apart from the time and the sun's angles (sky, turbidity,
// place, …). docs/accuracy.md ("Kept lighting") measures what keeping costs.
#pragma once

#include <optional>

#include "shading/lighting.h"

namespace skylit::view {

// The DNI's and the tone map reference's largest relative change under a kept lighting
// (the sun's angle alone would let a low sun's DNI change by ~10 % at sunrise).
inline constexpr double kLightingRelativeTolerance = 0.01;

class LightingReuse {
 public:
  // Angles in radians, ≥ 0: the whole lighting's, and the sky model's (≥ the first).
  LightingReuse(double max_sun_angle_rad, double max_sky_angle_rad);
  // `fresh`: resolve_lighting(request, …) of this frame.
  shading::Lighting next(const shading::LightingRequest& request, shading::Lighting fresh);

 private:
  double max_angle_, max_sky_angle_;
  std::optional<shading::LightingRequest> request_;  // the kept model's, time and sun angles cleared
  std::optional<shading::Lighting> made_;            // the lighting the kept model was made with
  std::optional<shading::Lighting> last_;            // the lighting handed back last
};

}  // namespace skylit::view
