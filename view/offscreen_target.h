// A framebuffer off screen (RGBA8 colour, 24-bit depth) to draw into where there is no
// window (headless `skylit render`, tests, tiled screenshots), read back as RGB rows.
#pragma once

#include <cstdint>
#include <vector>

namespace skylit::view {

// RGB8 of framebuffer `fbo` (0: the window's back buffer), the top row first (GL's rows
// start at the bottom).
std::vector<std::uint8_t> read_framebuffer_rgb(std::uint32_t fbo, int width, int height);

class OffscreenTarget {
 public:
  // Throws std::invalid_argument beyond GL_MAX_RENDERBUFFER_SIZE or for a side < 1.
  OffscreenTarget(int width, int height);
  ~OffscreenTarget();
  OffscreenTarget(const OffscreenTarget&) = delete;
  OffscreenTarget& operator=(const OffscreenTarget&) = delete;

  void bind() const;  // as the draw framebuffer, with the viewport set to it
  // RGB8, the top row of the image first (GL's rows start at the bottom).
  std::vector<std::uint8_t> read_rgb() const;
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  int width_, height_;
  std::uint32_t fbo_ = 0, colour_ = 0, depth_ = 0;
};

}  // namespace skylit::view
