#include "view/trail_draw.h"

#include <epoxy/gl.h>

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <limits>

#include "gpu/gl_context.h"

namespace skylit::view {
namespace {

constexpr int kVertexBinding = 3;  // the storage block of the trail's vertices

gpu::GlslDefines trail_defines() {
  gpu::GlslDefines d;
  d.set("TRAIL_BINDING", kVertexBinding);
  return d;
}

}  // namespace

TrailDraw::TrailDraw(std::span<const TrailPolyline> polylines)
    : program_("view_trail.vert", "view_trail.frag", trail_defines()) {
  time_origin_ = std::numeric_limits<double>::infinity();
  for (const TrailPolyline& p : polylines)
    for (const TrailVertex& v : p.vertices) time_origin_ = std::min(time_origin_, v.time_s);
  // Two vec4 per vertex (std430): position and time, colour.
  std::vector<float> packed;
  for (const TrailPolyline& p : polylines) {
    if (p.vertices.size() < 2) continue;
    firsts_.push_back(static_cast<std::int32_t>(times_.size()));
    for (const TrailVertex& v : p.vertices) {
      packed.insert(packed.end(), {static_cast<float>(v.position.x), static_cast<float>(v.position.y),
                                   static_cast<float>(v.position.z), static_cast<float>(v.time_s - time_origin_),
                                   v.colour.r, v.colour.g, v.colour.b, 1.0f});
      times_.push_back(v.time_s);
    }
    ends_.push_back(static_cast<std::int32_t>(times_.size()));
  }
  counts_.resize(firsts_.size());
  for (std::int32_t first : firsts_) segment_firsts_.push_back(6 * first);  // six vertices a segment
  if (!packed.empty()) vertices_ = gpu::Buffer::from(std::span<const float>(packed));
  glCreateVertexArrays(1, &vao_);
  gpu::throw_on_gl_error("TrailDraw");
}

TrailDraw::~TrailDraw() { glDeleteVertexArrays(1, &vao_); }

void TrailDraw::draw(const glm::dmat4& view_proj, double exaggeration, const CurvatureDrop& drop, double drawn_until_s,
                     double width_px) {
  if (firsts_.empty()) return;
  // Up to the first vertex after the cut (the fragment stage drops that segment's rest):
  // its segments, the k-th from vertex first + k.
  for (std::size_t k = 0; k < firsts_.size(); ++k) {
    const auto begin = times_.begin() + firsts_[k], end = times_.begin() + ends_[k];
    const auto after = std::upper_bound(begin, end, drawn_until_s);
    const auto vertices = static_cast<std::int32_t>(after == begin ? 0 : (after == end ? end : after + 1) - begin);
    counts_[k] = 6 * std::max(vertices - 1, 0);
  }
  GLint viewport[4] = {0, 0, 1, 1};
  glGetIntegerv(GL_VIEWPORT, viewport);
  const glm::mat4 vp(view_proj);
  program_.use();
  program_.set_mat4("view_proj", glm::value_ptr(vp));
  program_.set("exaggeration", static_cast<float>(exaggeration));
  set_curvature_uniforms(program_, drop);
  program_.set("drawn_until", static_cast<float>(drawn_until_s - time_origin_));
  program_.set("width_px", static_cast<float>(width_px));
  program_.set("viewport", static_cast<float>(viewport[2]), static_cast<float>(viewport[3]));
  vertices_.bind_storage(kVertexBinding);
  glBindVertexArray(vao_);
  glMultiDrawArrays(GL_TRIANGLES, segment_firsts_.data(), counts_.data(), static_cast<GLsizei>(firsts_.size()));
  glBindVertexArray(0);
  gpu::throw_on_gl_error("TrailDraw::draw");
}

}  // namespace skylit::view
