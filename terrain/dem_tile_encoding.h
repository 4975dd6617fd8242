// Heights as RGB for DEM tiles (MapLibre/Mapbox `raster-dem`): both encodings store a
// 24-bit code c = R·65536 + G·256 + B, and h = base + c / codes_per_metre:
//  * Mapbox Terrain-RGB: h = −10000 + c · 0.1 (0.1 m steps, −10000 … 1667721.5 m);
//  * Terrarium:          h = R·256 + G + B/256 − 32768 = c/256 − 32768 (1/256 m steps,
//                        −32768 … 32767.996 m).
// Policy (tests rely on it):
//  * Encoding rounds to the nearest step (ties upward) and clamps to the code range,
//    so a decoded height is within half a step of the input when it is in range.
//    A NaN height encodes as 0 m.
//  * Nodata: alpha 0. The RGB under it still encodes the pixel's (filled) height, not
//    code 0, because clients that ignore alpha would otherwise decode Terrarium
//    (0, 0, 0) as −32768 m (Terrain-RGB as −10000 m) and draw a pit at every void and
//    tile edge. Valid pixels have alpha 255. Writers must keep RGB under alpha 0
//    (lossless PNG does; WebP needs its "exact" mode).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "terrain/height_field.h"

namespace skylit::terrain {

enum class DemEncoding { TerrainRgb, Terrarium };

struct DemEncodingParams {
  double base_m = 0.0;           // height of code 0
  double codes_per_metre = 1.0;  // 10 (Terrain-RGB), 256 (Terrarium); exact in binary
  double step() const { return 1.0 / codes_per_metre; }
  double min_height() const { return base_m; }
  double max_height() const;     // base + (2^24 − 1) / codes_per_metre
};

DemEncodingParams encoding_params(DemEncoding e);
// MapLibre's `encoding` names: "mapbox", "terrarium".
std::string_view encoding_name(DemEncoding e);
std::optional<DemEncoding> parse_dem_encoding(std::string_view name);

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb&) const = default;
};

Rgb encode_height(DemEncoding e, double height_m);
double decode_height(DemEncoding e, const Rgb& rgb);

// The pixels of `rect` (inside `field`, e.g. TileWindow::tile_rect) as RGBA rows,
// pixel-interleaved (rect.width · rect.height · 4 bytes), by the nodata policy above.
// Throws std::invalid_argument when rect is not inside the field or rgba is too small.
void encode_dem_tile(DemEncoding e, const HeightField& field, const PixelRect& rect, std::span<std::uint8_t> rgba);

}  // namespace skylit::terrain
