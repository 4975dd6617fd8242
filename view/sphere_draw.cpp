#include "view/sphere_draw.h"

#include <epoxy/gl.h>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <vector>

#include "gpu/gl_context.h"
#include "view/display_defines.h"

namespace skylit::view {

SphereDraw::SphereDraw() : program_("view_spheres.vert", "view_spheres.frag", display_code_defines()) {
  glCreateVertexArrays(1, &vao_);
}

void SphereDraw::draw(std::span<const blockers::Sphere> spheres, const glm::dmat4& view, const glm::dmat4& proj,
                      double exaggeration, const CurvatureDrop& drop, const SkyLight& light, bool srgb) {
  if (spheres.empty()) return;
  std::vector<float> packed;
  packed.reserve(spheres.size() * 4);
  for (const blockers::Sphere& s : spheres)
    packed.insert(packed.end(), {static_cast<float>(s.centre.x), static_cast<float>(s.centre.y),
                                 static_cast<float>(s.centre.z), static_cast<float>(s.radius)});
  const std::size_t bytes = packed.size() * sizeof(float);
  if (spheres_.size_bytes() < bytes) spheres_ = gpu::Buffer(bytes);
  spheres_.upload(packed.data(), bytes);

  const glm::mat4 v(view), p(proj);
  const glm::mat3 to_world(glm::transpose(glm::dmat3(view)));  // the view's rotation is orthonormal
  program_.use();
  program_.set_mat4("view", glm::value_ptr(v));
  program_.set_mat4("proj", glm::value_ptr(p));
  program_.set_mat3("view_to_world", glm::value_ptr(to_world));
  program_.set("exaggeration", static_cast<float>(exaggeration));
  set_curvature_uniforms(program_, drop);
  const glm::vec3 s(light.sun_direction), sun(light.sun_up ? light.sun_on_facing : glm::dvec3(0.0)),
      sky(light.sky_on_horizontal);
  program_.set("sun_dir", s.x, s.y, s.z);
  program_.set("sun_display", sun.x, sun.y, sun.z);
  program_.set("sky_display", sky.x, sky.y, sky.z);
  program_.set("body_albedo", static_cast<float>(kBodyAlbedo));
  program_.set("srgb", srgb ? 1 : 0);
  spheres_.bind_storage(2);
  glBindVertexArray(vao_);
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(spheres.size()));
  glBindVertexArray(0);
  gpu::throw_on_gl_error("SphereDraw::draw");
}

}  // namespace skylit::view
