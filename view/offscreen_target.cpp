#include "view/offscreen_target.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "gpu/gl_context.h"

namespace skylit::view {

OffscreenTarget::OffscreenTarget(int width, int height) : width_(width), height_(height) {
  GLint max_side = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_side);
  if (width < 1 || height < 1 || width > max_side || height > max_side)
    throw std::invalid_argument("a " + std::to_string(width) + "x" + std::to_string(height) +
                                " frame is outside this GPU's 1 .. " + std::to_string(max_side) + " pixels a side");
  glCreateFramebuffers(1, &fbo_);
  glCreateRenderbuffers(1, &colour_);
  glCreateRenderbuffers(1, &depth_);
  glNamedRenderbufferStorage(colour_, GL_RGBA8, width, height);
  glNamedRenderbufferStorage(depth_, GL_DEPTH_COMPONENT24, width, height);
  glNamedFramebufferRenderbuffer(fbo_, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
  glNamedFramebufferRenderbuffer(fbo_, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  if (glCheckNamedFramebufferStatus(fbo_, GL_DRAW_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("the off-screen framebuffer is incomplete on this driver");
  gpu::throw_on_gl_error("OffscreenTarget");
}

OffscreenTarget::~OffscreenTarget() {
  glDeleteFramebuffers(1, &fbo_);
  glDeleteRenderbuffers(1, &colour_);
  glDeleteRenderbuffers(1, &depth_);
}

void OffscreenTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, width_, height_);
}

std::vector<std::uint8_t> read_framebuffer_rgb(std::uint32_t fbo, int width, int height) {
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(width) * height * 3);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
  if (fbo == 0) glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
  const std::size_t row = static_cast<std::size_t>(width) * 3;
  for (int j = 0; j < height / 2; ++j)
    std::swap_ranges(rgb.begin() + j * row, rgb.begin() + (j + 1) * row, rgb.begin() + (height - 1 - j) * row);
  gpu::throw_on_gl_error("read_framebuffer_rgb");
  return rgb;
}

std::vector<std::uint8_t> OffscreenTarget::read_rgb() const { return read_framebuffer_rgb(fbo_, width_, height_); }

}  // namespace skylit::view
