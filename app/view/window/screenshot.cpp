#include "app/view/window/screenshot.h"

#include <algorithm>
#include <ctime>
#include <filesystem>
#include <stdexcept>

#include "app/view/frame_sink.h"
#include "view/offscreen_target.h"

namespace skylit::app::view::window {

namespace fs = std::filesystem;
namespace sv = skylit::view;

RgbImage render_tiled(sv::SceneView& scene, const sv::ViewFrame& frame, int width, int height, int scale) {
  RgbImage out{width * scale, height * scale, {}};
  out.rgb.resize(static_cast<std::size_t>(out.width) * out.height * 3);
  sv::OffscreenTarget target(width, height);
  const double n = scale;
  for (int ty = 0; ty < scale; ++ty)    // from the bottom, as NDC
    for (int tx = 0; tx < scale; ++tx) {
      // Clip coordinates of the whole to the tile's: x' = n·x − (2·tx + 1 − n)·w.
      glm::dmat4 window(1.0);
      window[0][0] = n;
      window[1][1] = n;
      window[3][0] = -(2.0 * tx + 1.0 - n);
      window[3][1] = -(2.0 * ty + 1.0 - n);
      sv::ViewFrame tile = frame;
      tile.camera.proj = window * frame.camera.proj;
      tile.camera.pixels_per_radian = frame.camera.pixels_per_radian * n;
      tile.reuse_shading = tx + ty > 0;
      target.bind();
      scene.draw(tile, width, height);
      const std::vector<std::uint8_t> rgb = target.read_rgb();
      const int row0 = (scale - 1 - ty) * height, col0 = tx * width;
      for (int r = 0; r < height; ++r)
        std::copy_n(rgb.begin() + static_cast<std::ptrdiff_t>(r) * width * 3, width * 3,
                    out.rgb.begin() + (static_cast<std::ptrdiff_t>(row0 + r) * out.width + col0) * 3);
    }
  return out;
}

void check_screenshot_path(const std::string& path, bool overwrite) {
  const fs::path p(path);
  check_folder(p, "screenshot");
  check_absent(p, overwrite, "screenshot");
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext != ".png") throw std::invalid_argument("screenshot '" + path + "': only .png is written");
}

void write_screenshot(const std::string& path, const RgbImage& image, bool overwrite) {
  check_screenshot_path(path, overwrite);
  write_rgb_png(path, image.width, image.height, image.rgb, overwrite);
}

std::string default_screenshot_name() {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "skylit-%Y%m%d-%H%M%S", &local);
  std::string name = std::string(stamp) + ".png";
  for (int k = 2; fs::exists(name); ++k) name = std::string(stamp) + "-" + std::to_string(k) + ".png";
  return name;
}

}  // namespace skylit::app::view::window
