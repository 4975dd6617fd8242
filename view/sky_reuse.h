// The frames' sky model, kept while the sun moves little: each frame resolves its
// lighting at its own time, and SkyReuse hands it back with the sky model of an earlier
// frame while the sun has moved less than kSunTolerance since that model was made and
// the request is otherwise the same (sky, turbidity, place, …; not the time or sun
// angles, which only place the sun). The renderer then keeps
// the sky's tables and each texel's sky irradiance (GpuRenderer::keep_sky_irradiance);
// the sun itself (direction, DNI) and the tone map's reference are always the frame's.
#pragma once

#include <optional>

#include "shading/lighting.h"

namespace skylit::view {

class SkyReuse {
 public:
  explicit SkyReuse(double max_sun_angle_rad);
  // `fresh`: resolve_lighting(request, …) of this frame.
  shading::Lighting next(const shading::LightingRequest& request, shading::Lighting fresh);

 private:
  double max_angle_;
  std::optional<shading::LightingRequest> request_;  // the kept model's, time and sun angles cleared
  std::optional<shading::Lighting> made_;            // the lighting the kept model was made with
};

}  // namespace skylit::view
