// One tile's pixels as an RGBA image and its PNG, WebP or JPEG bytes. Shaded products become grey (or
// the colour sky's RGB) with alpha 0 at nodata and outside the DEM; DEM encodings use
// terrain/dem_tile_encoding.h.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "shading/products.h"
#include "terrain/height_field.h"
#include "tiles/metadata.h"

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

// The bounding box of the valid pixels of `field` inside `rect`; empty when there are
// none (tiles without one are not written).
terrain::PixelRect valid_bounds(const terrain::HeightField& field, const terrain::PixelRect& rect);

// The bytes of size × size RGBA pixels in `format` (deterministic: no time or software
// stamp). PNG and WebP are lossless with alpha (WebP: libwebp's exact lossless mode, so a
// tile decodes to the PNG's pixels, RGB under alpha 0 included); JPEG has no alpha: transparent pixels become white, the
// rest is compressed at quality 90 (for opaque base maps).
// png_zlevel: zlib's level for PNG (ignored by the other formats).
std::string encode_tile(skylit::tiles::TileFormat format, int size, const std::vector<std::uint8_t>& rgba,
                        int png_zlevel);
// zlib levels, measured on Big Tujunga z 10–13 (85 tiles, docs/performance.md, session 12):
// shaded relief compresses to within 0.4 % of level 6's bytes at level 3 in 0.39× the
// time; Terrain-RGB grows 9.5 % at level 3, bytes every client downloads, so the DEM
// encodings keep zlib's default.
inline constexpr int kShadedPngZlevel = 3;
inline constexpr int kDemPngZlevel = 6;
// Background of transparent pixels in JPEG tiles.
inline constexpr std::uint8_t kJpegBackground = 255;

}  // namespace skylit::app::tiles
