// A user sky from an equirectangular (latitude–longitude) HDR image.
//
// Orientation: width = 2 × height. Row 0 is at the zenith and the last row at
// the nadir (θ = π·(row + ½)/H at texel centres); the left edge is north and
// azimuth grows to the right, clockwise seen from above (N, E, S, W at
// u = 0, ¼, ½, ¾; geographic azimuth A = 2π·(col + ½)/W at centres) — the view
// of a panorama from inside. The lower half is ignored (sky = 0 below the
// horizon). Pixel values × `scale` are RGB radiance in W m⁻² sr⁻¹ (first three
// channels; one channel is read as grey). Lookup is bilinear, wrapping in azimuth.
//
// Sun in the map: with sun_clamp > 0, every texel whose luminance exceeds it
// (after scaling) is scaled down to that luminance, keeping its colour. That
// removes the disc's energy (the sun is the separate key light) and keeps the
// aureole; choose the threshold above the brightest sky (e.g. 10–50× the zenith).
#pragma once

#include "shading/sky/sky_model.h"

#include <string>
#include <vector>

namespace skylit::sky {

struct EnvMapOptions {
  double scale = 1.0;      // multiplies pixel values
  double sun_clamp = 0.0;  // luminance cap (W m⁻² sr⁻¹); ≤ 0: off
};

class EnvMapSky final : public SkyModel {
 public:
  // rgb: height rows of width RGB triples, top row first. Throws
  // std::invalid_argument unless width == 2·height ≥ 2 and values are finite
  // (negative values are clamped to 0).
  EnvMapSky(int width, int height, std::vector<float> rgb, const EnvMapOptions& opt = {});
  // Reads any format OpenImageIO reads (EXR, HDR, ...); throws
  // std::runtime_error if unreadable, std::invalid_argument if not 2:1.
  static EnvMapSky load(const std::string& path, const EnvMapOptions& opt = {});

  Rgb radiance(const glm::dvec3& dir) const override;
  Rgb texel(int row, int col) const;
  int width() const { return width_; }
  int height() const { return height_; }
  // Unit direction of a texel centre.
  glm::dvec3 texel_direction(int row, int col) const;

 private:
  int width_, height_;
  std::vector<float> rgb_;
};

}  // namespace skylit::sky
