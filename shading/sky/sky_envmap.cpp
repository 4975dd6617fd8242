#include "shading/sky/sky_envmap.h"

#include "shading/sh/sh_basis.h"

#include "imageio/image_reader.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace skylit::sky {

EnvMapSky::EnvMapSky(int width, int height, std::vector<float> rgb, const EnvMapOptions& opt)
    : width_(width), height_(height), rgb_(std::move(rgb)) {
  if (height < 1 || width != 2 * height)
    throw std::invalid_argument("environment map must be equirectangular with width = 2 × height, got " +
                                std::to_string(width) + " × " + std::to_string(height));
  if (rgb_.size() != static_cast<std::size_t>(width) * height * 3)
    throw std::invalid_argument("environment map: pixel buffer size does not match width × height × 3");
  for (std::size_t i = 0; i < rgb_.size(); i += 3) {
    Rgb c(rgb_[i], rgb_[i + 1], rgb_[i + 2]);
    if (!std::isfinite(c.r) || !std::isfinite(c.g) || !std::isfinite(c.b))
      throw std::invalid_argument("environment map: non-finite pixel value");
    c = glm::max(c * opt.scale, Rgb(0.0));
    const double lum = luminance(c);
    if (opt.sun_clamp > 0.0 && lum > opt.sun_clamp) c *= opt.sun_clamp / lum;
    for (int k = 0; k < 3; ++k) rgb_[i + k] = static_cast<float>(c[k]);
  }
}

EnvMapSky EnvMapSky::load(const std::string& path, const EnvMapOptions& opt) {
  imageio::FloatImage image;
  try {
    image = imageio::read_float_image(path, 3);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(std::string("environment map: ") + e.what());
  }
  const int w = image.width, h = image.height, n = image.channels;
  if (h < 1 || w != 2 * h)
    throw std::invalid_argument("environment map '" + path + "' is " + std::to_string(w) + " × " +
                                std::to_string(h) + "; an equirectangular map needs width = 2 × height");
  std::vector<float> rgb(static_cast<std::size_t>(w) * h * 3);
  for (std::size_t p = 0; p < static_cast<std::size_t>(w) * h; ++p)
    for (int k = 0; k < 3; ++k) rgb[3 * p + k] = image.pixels[n * p + std::min(k, n - 1)];
  return EnvMapSky(w, h, std::move(rgb), opt);
}

Rgb EnvMapSky::texel(int row, int col) const {
  const std::size_t i = 3 * (static_cast<std::size_t>(row) * width_ + col);
  return {rgb_[i], rgb_[i + 1], rgb_[i + 2]};
}

glm::dvec3 EnvMapSky::texel_direction(int row, int col) const {
  const double theta = sh::kPi * (row + 0.5) / height_;
  const double azimuth = 2.0 * sh::kPi * (col + 0.5) / width_;
  return direction_from_azimuth_elevation(azimuth, sh::kPi / 2.0 - theta);
}

Rgb EnvMapSky::radiance(const glm::dvec3& dir) const {
  if (dir.z <= 0.0) return Rgb(0.0);
  const double u = azimuth_of(dir) / (2.0 * sh::kPi) * width_ - 0.5;
  const double v = std::acos(std::min(dir.z, 1.0)) / sh::kPi * height_ - 0.5;
  const double fu = std::floor(u), fv = std::floor(v);
  const double tu = u - fu, tv = v - fv;
  const int c0 = (static_cast<int>(fu) % width_ + width_) % width_, c1 = (c0 + 1) % width_;
  // Rows clamp at the poles (above the first row centre the top row is used).
  const int r0 = std::clamp(static_cast<int>(fv), 0, height_ - 1);
  const int r1 = std::clamp(static_cast<int>(fv) + 1, 0, height_ - 1);
  return (1 - tv) * ((1 - tu) * texel(r0, c0) + tu * texel(r0, c1)) +
         tv * ((1 - tu) * texel(r1, c0) + tu * texel(r1, c1));
}

}  // namespace skylit::sky
