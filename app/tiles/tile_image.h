// One tile's pixels as an RGBA image and its PNG bytes. Shaded products become grey (or
// the colour sky's RGB) with alpha 0 at nodata and outside the DEM; DEM encodings use
// terrain/dem_tile_encoding.h.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "shading/products.h"
#include "terrain/height_field.h"

namespace skylit::app::tiles {

// Irradiance (W m⁻²) at code 255: the solar constant, above any sunlit slope's
// direct-plus-sky irradiance on clear days.
inline constexpr double kIrradianceFullScale = 1361.0;

// 8-bit code of a product value: eight-bit products (shaded, hillshade) as they are
// (1…255), irradiance scaled by kIrradianceFullScale, fractions (svf, skyview, shadow)
// times 255; rounded and clamped to 0…255.
std::uint8_t product_code(shading::Product product, float value);

// The pixels `rect` of a frame's bands (one grey band, or R, G, B) as RGBA rows; alpha 0
// (and RGB 0) where the field is not valid or the value is not finite.
std::vector<std::uint8_t> product_tile_rgba(shading::Product product, const shading::ProductBands& bands,
                                            const terrain::HeightField& field, const terrain::PixelRect& rect);

// True when `rect` holds at least one valid pixel of `field` (tiles without one are not written).
bool any_valid(const terrain::HeightField& field, const terrain::PixelRect& rect);

// PNG bytes of size × size RGBA pixels (deterministic: no time or software stamp).
std::string encode_png(int size, const std::vector<std::uint8_t>& rgba);

}  // namespace skylit::app::tiles
