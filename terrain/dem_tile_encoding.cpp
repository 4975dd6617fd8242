// Terrain-RGB and Terrarium height codes.
#include "terrain/dem_tile_encoding.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace skylit::terrain {
namespace {

constexpr double kMaxCode = 16777215.0;  // 2^24 − 1

}  // namespace

double DemEncodingParams::max_height() const { return base_m + kMaxCode / codes_per_metre; }

DemEncodingParams encoding_params(DemEncoding e) {
  switch (e) {
    case DemEncoding::TerrainRgb: return {-10000.0, 10.0};
    case DemEncoding::Terrarium: return {-32768.0, 256.0};
  }
  throw std::invalid_argument("unknown DEM encoding");
}

std::string_view encoding_name(DemEncoding e) { return e == DemEncoding::Terrarium ? "terrarium" : "mapbox"; }

std::optional<DemEncoding> parse_dem_encoding(std::string_view name) {
  if (name == "mapbox" || name == "terrain-rgb") return DemEncoding::TerrainRgb;
  if (name == "terrarium") return DemEncoding::Terrarium;
  return std::nullopt;
}

Rgb encode_height(DemEncoding e, double height_m) {
  const DemEncodingParams p = encoding_params(e);
  const double h = std::isnan(height_m) ? 0.0 : height_m;
  const double code = std::clamp(std::floor((h - p.base_m) * p.codes_per_metre + 0.5), 0.0, kMaxCode);
  const auto c = static_cast<std::uint32_t>(code);
  return {static_cast<std::uint8_t>(c >> 16), static_cast<std::uint8_t>((c >> 8) & 0xff),
          static_cast<std::uint8_t>(c & 0xff)};
}

double decode_height(DemEncoding e, const Rgb& rgb) {
  const DemEncodingParams p = encoding_params(e);
  const double code = rgb.r * 65536.0 + rgb.g * 256.0 + rgb.b;
  return p.base_m + code / p.codes_per_metre;
}

void encode_dem_tile(DemEncoding e, const HeightField& field, const PixelRect& rect, std::span<std::uint8_t> rgba) {
  if (rect.empty() || rect.x0 < 0 || rect.y0 < 0 || rect.x1() > field.width || rect.y1() > field.height)
    throw std::invalid_argument("encode_dem_tile: the rectangle is empty or not inside the " +
                                std::to_string(field.width) + "×" + std::to_string(field.height) + " field");
  const std::size_t need = static_cast<std::size_t>(rect.width) * rect.height * 4;
  if (rgba.size() < need)
    throw std::invalid_argument("encode_dem_tile: the output holds " + std::to_string(rgba.size()) + " bytes, " +
                                std::to_string(need) + " needed");
  std::size_t k = 0;
  for (int j = rect.y0; j < rect.y1(); ++j)
    for (int i = rect.x0; i < rect.x1(); ++i) {
      const Rgb c = encode_height(e, field.at(i, j));
      rgba[k++] = c.r;
      rgba[k++] = c.g;
      rgba[k++] = c.b;
      rgba[k++] = field.is_valid(i, j) ? 255 : 0;
    }
}

}  // namespace skylit::terrain
