// The sky behind the terrain and the light on the aircraft's bodies, from the frame's
// lighting (shading/lighting.h) in the terrain's display units: a white Lambertian
// surface under irradiance E shows E · k, with k the frame's display scale (lit frames)
// or scale / π (the unlit `shaded`, whose values are radiances), so the sky of radiance
// L shows π · L · k, the value of white ground under a uniform sky of that radiance,
// times the sky's exposure (sky_draw.cpp: the terrain stands for ground of albedo 0.3).
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <optional>

#include "gpu/buffers.h"
#include "gpu/graphics_program.h"
#include "shading/lighting.h"
#include "shading/products.h"

namespace skylit::view {

// Display values of what lights a body, and of the sky map itself.
struct SkyLight {
  glm::dvec3 sky_on_horizontal{0.0};  // a white horizontal surface under the sky alone
  glm::dvec3 sun_on_facing{0.0};      // a white surface facing the sun, the sun alone
  glm::dvec3 sun_direction{0.0, 0.0, 1.0};
  bool sun_up = false;
};

// The sky's radiance baked at the centres of an azimuth × elevation grid (display
// values, RGB, row 0 at the horizon), and the SkyLight from the same lighting.
// No lighting: the unlit `shaded`'s uniform sky of radiance 1, no sun.
struct SkyMap {
  int azimuths = 0, elevations = 0;
  std::vector<float> rgb;  // (e · azimuths + a) · 3 + c
  SkyLight light;
};
SkyMap bake_sky(const std::optional<shading::Lighting>& lighting, double display_scale, int azimuths = 96,
                int elevations = 24);

class SkyDraw {
 public:
  SkyDraw();
  // Rebakes the map as 8-bit display codes under `tone` (the caller calls it when the
  // lighting, its display scale or the tone changes).
  void set(const SkyMap& map, shading::ToneCurve tone);
  const SkyLight& light() const { return light_; }
  void draw(const glm::dmat4& view_proj);

 private:
  gpu::GraphicsProgram program_;
  gpu::Texture2D map_;
  SkyLight light_;
  float sun_code_ = 1.0f;  // the disc's display code / 255
  std::uint32_t vao_ = 0;
};

}  // namespace skylit::view
