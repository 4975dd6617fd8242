#include "view/sky_draw.h"

#include <epoxy/gl.h>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <numbers>

#include "gpu/gl_context.h"
#include "shading/sky/sky_model.h"

namespace skylit::view {
namespace {

constexpr double kPi = std::numbers::pi;
// The drawn disc is a few times the real sun's 0.27° so that it is seen at all.
constexpr double kDrawnSunRadiusDeg = 0.8;
// The terrain is drawn as a white surface; a camera exposed for real ground (albedo
// about 0.3) sees the sky 1/0.3 times brighter against it than against white ground.
constexpr double kSkyExposure = 1.0 / 0.3;
// The disc's display value: saturated, as it is far brighter than any surface.
constexpr double kSunDisplay = 1e3;

}  // namespace

SkyMap bake_sky(const std::optional<shading::Lighting>& lighting, double display_scale, int azimuths, int elevations) {
  SkyMap m;
  m.azimuths = azimuths;
  m.elevations = elevations;
  m.rgb.resize(static_cast<std::size_t>(azimuths) * elevations * 3);
  const double k = lighting ? display_scale : display_scale / kPi;
  const sky::UniformSky unit_sky;
  const sky::SkyModel* sky = lighting ? lighting->sky.get() : &unit_sky;
  glm::dvec3 e_sky(0.0);
  const double da = 2.0 * kPi / azimuths, de = 0.5 * kPi / elevations;
  for (int e = 0; e < elevations; ++e)
    for (int a = 0; a < azimuths; ++a) {
      const double elevation = (e + 0.5) * de, azimuth = (a + 0.5) * da;
      const glm::dvec3 dir = sky::direction_from_azimuth_elevation(azimuth, elevation);
      const glm::dvec3 L = sky ? sky->radiance(dir) : glm::dvec3(0.0);
      // Midpoint rule of E = ∫ L sin(e) cos(e) de da (sin e: the cosine to the zenith).
      e_sky += L * std::sin(elevation) * std::cos(elevation) * de * da;
      for (int c = 0; c < 3; ++c)
        m.rgb[(static_cast<std::size_t>(e) * azimuths + a) * 3 + c] = static_cast<float>(kPi * L[c] * k * kSkyExposure);
    }
  m.light.sky_on_horizontal = e_sky * k;
  if (lighting) {
    m.light.sun_direction = lighting->sun.direction;
    m.light.sun_on_facing = lighting->sun.dni * k;
    m.light.sun_up = lighting->sun.direction.z > 0.0 && sky::luminance(lighting->sun.dni) > 0.0;
  }
  return m;
}

SkyDraw::SkyDraw() : program_("view_sky.vert", "view_sky.frag") {
  glCreateVertexArrays(1, &vao_);
}

void SkyDraw::set(const SkyMap& map, shading::ToneCurve tone) {
  if (map_.width() != map.azimuths || map_.height() != map.elevations) {
    map_ = gpu::Texture2D(map.azimuths, map.elevations, gpu::TextureFormat::RGBA8);
    map_.set_linear_filter();
    glTextureParameteri(map_.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(map_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  std::vector<float> rgba(static_cast<std::size_t>(map.azimuths) * map.elevations * 4, 1.0f);
  // Codes, as the terrain's colour map holds them: the fragments filter them and write them.
  auto code = [&](double display) { return static_cast<float>(shading::display_code_value(display, tone) / 255.0); };
  for (std::size_t t = 0; t < rgba.size() / 4; ++t)
    for (int c = 0; c < 3; ++c) rgba[t * 4 + c] = code(map.rgb[t * 3 + c]);
  map_.upload(rgba);
  light_ = map.light;
  sun_code_ = code(kSunDisplay);
  gpu::throw_on_gl_error("SkyDraw::set");
}

void SkyDraw::draw(const glm::dmat4& view_proj) {
  const glm::mat4 inv(glm::inverse(view_proj));
  program_.use();
  program_.set_mat4("inverse_view_proj", glm::value_ptr(inv));
  const glm::vec3 s(light_.sun_direction);
  program_.set("sun_dir", s.x, s.y, s.z);
  program_.set("sun_cos_radius", light_.sun_up ? static_cast<float>(std::cos(kDrawnSunRadiusDeg * kPi / 180.0)) : 2.0f);
  program_.set("sun_code", sun_code_, sun_code_, sun_code_);
  map_.bind_sampler(1);
  glBindVertexArray(vao_);
  glDepthFunc(GL_LEQUAL);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDepthFunc(GL_LESS);
  glBindVertexArray(0);
  gpu::throw_on_gl_error("SkyDraw::draw");
}

}  // namespace skylit::view
