// Draws the aircraft as their sphere sets (exact ray-cast spheres on instanced squares,
// with depth), lit by the frame's sky and sun (sky_draw.h's SkyLight).
#pragma once

#include <glm/mat4x4.hpp>

#include <span>

#include "gpu/buffers.h"
#include "gpu/graphics_program.h"
#include "shading/blockers/sphere_blocker.h"
#include "view/curvature_drop.h"
#include "view/sky_draw.h"

namespace skylit::view {

// Light grey: painted aircraft, gliders white.
inline constexpr double kBodyAlbedo = 0.75;

class SphereDraw {
 public:
  SphereDraw();
  void draw(std::span<const blockers::Sphere> spheres, const glm::dmat4& view, const glm::dmat4& proj,
            double exaggeration, const CurvatureDrop& drop, const SkyLight& light, bool srgb);

 private:
  gpu::GraphicsProgram program_;
  gpu::Buffer spheres_;
  std::uint32_t vao_ = 0;
};

}  // namespace skylit::view
