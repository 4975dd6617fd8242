#include "app/tiles/tile_image.h"

#include <cpl_conv.h>
#include <cpl_vsi.h>
#include <gdal_priv.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace skylit::app::tiles {

std::uint8_t product_code(shading::Product product, float value) {
  double v = value;
  if (product == shading::Product::Irradiance) v *= 255.0 / kIrradianceFullScale;
  else if (!shading::traits(product).eight_bit) v *= 255.0;
  return static_cast<std::uint8_t>(std::clamp(std::lround(v), 0L, 255L));
}

std::vector<std::uint8_t> product_tile_rgba(shading::Product product, const shading::ProductBands& bands,
                                            const terrain::HeightField& field, const terrain::PixelRect& rect) {
  if (bands.width != field.width || bands.height != field.height || (bands.bands != 1 && bands.bands != 3))
    throw std::invalid_argument("tile image: the frame's bands do not match the window");
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(rect.width) * rect.height * 4, 0);
  for (int j = 0; j < rect.height; ++j)
    for (int i = 0; i < rect.width; ++i) {
      const int x = rect.x0 + i, y = rect.y0 + j;
      std::uint8_t* px = &rgba[(static_cast<std::size_t>(j) * rect.width + i) * 4];
      if (!field.is_valid(x, y)) continue;
      bool finite = true;
      for (int c = 0; c < 3; ++c) {
        const float v = bands.at(bands.bands == 3 ? c : 0, x, y);
        finite = finite && std::isfinite(v);
        px[c] = finite ? product_code(product, v) : 0;
      }
      if (finite) px[3] = 255;
      else std::fill(px, px + 4, std::uint8_t{0});
    }
  return rgba;
}

terrain::PixelRect valid_bounds(const terrain::HeightField& field, const terrain::PixelRect& rect) {
  int x0 = rect.x1(), x1 = rect.x0 - 1, y0 = rect.y1(), y1 = rect.y0 - 1;
  for (int y = rect.y0; y < rect.y1(); ++y) {
    const std::uint8_t* row = field.valid.data() + static_cast<std::size_t>(y) * field.width;
    const std::uint8_t* first = std::find(row + rect.x0, row + rect.x1(), std::uint8_t{1});
    if (first == row + rect.x1()) continue;
    const std::uint8_t* last = std::find(std::make_reverse_iterator(row + rect.x1()), std::make_reverse_iterator(first),
                                         std::uint8_t{1}).base() - 1;
    x0 = std::min(x0, static_cast<int>(first - row));
    x1 = std::max(x1, static_cast<int>(last - row));
    y0 = std::min(y0, y);
    y1 = y;
  }
  return x1 < x0 ? terrain::PixelRect{} : terrain::PixelRect{x0, y0, x1 - x0 + 1, y1 - y0 + 1};
}

std::string encode_tile(skylit::tiles::TileFormat format, int size, const std::vector<std::uint8_t>& rgba,
                        int png_zlevel) {
  using skylit::tiles::TileFormat;
  // Tiles are encoded on every core, and GDALAllRegister rescans its plugin path on each
  // call without a lock (a data race ThreadSanitizer shows): register once.
  static std::once_flag registered;
  std::call_once(registered, [] { GDALAllRegister(); });
  const char* driver_name = format == TileFormat::Png ? "PNG" : format == TileFormat::Webp ? "WEBP" : "JPEG";
  GDALDriver* mem = GetGDALDriverManager()->GetDriverByName("MEM");
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(driver_name);
  if (!mem || !driver) throw std::runtime_error(std::string("GDAL lacks its MEM or ") + driver_name + " driver");
  const bool alpha = format != TileFormat::Jpeg;
  std::vector<std::uint8_t> pixels = rgba;
  if (!alpha)  // JPEG: composite over the background, RGB only
    for (std::size_t k = 0; k < pixels.size(); k += 4)
      if (pixels[k + 3] == 0) std::fill(&pixels[k], &pixels[k + 3], kJpegBackground);
  const int bands = alpha ? 4 : 3;
  std::unique_ptr<GDALDataset> src(mem->Create("", size, size, bands, GDT_Byte, nullptr));
  if (!src) throw std::runtime_error("cannot create an in-memory tile");
  // Pixel-interleaved RGBA rows into the bands (the first three for JPEG).
  if (src->RasterIO(GF_Write, 0, 0, size, size, pixels.data(), size, size, GDT_Byte, bands, nullptr, 4, 4 * size, 1) !=
      CE_None)
    throw std::runtime_error("cannot fill an in-memory tile");
  if (alpha) src->GetRasterBand(4)->SetColorInterpretation(GCI_AlphaBand);
  // A unique /vsimem/ name per thread; no .aux.xml beside it (GDAL_PAM_ENABLED off).
  const std::string name = "/vsimem/skylit_tile_" + std::to_string(reinterpret_cast<std::uintptr_t>(&size)) + "." +
                           std::string(skylit::tiles::format_name(format));
  CPLSetThreadLocalConfigOption("GDAL_PAM_ENABLED", "NO");
  const std::string zlevel = "ZLEVEL=" + std::to_string(png_zlevel);
  std::vector<const char*> options = {"WORLDFILE=NO", zlevel.c_str()};
  // Lossless, and EXACT: libwebp would otherwise recolour transparent pixels, where DEM
  // encodings keep the filled height's code (terrain/dem_tile_encoding.h). QUALITY is
  // the effort when lossless.
  if (format == TileFormat::Webp) options = {"LOSSLESS=YES", "EXACT=1", "QUALITY=100"};
  if (format == TileFormat::Jpeg) options = {"WORLDFILE=NO", "QUALITY=90"};
  options.push_back(nullptr);
  std::unique_ptr<GDALDataset> out(driver->CreateCopy(name.c_str(), src.get(), FALSE, const_cast<char**>(options.data()),
                                                      nullptr, nullptr));
  if (!out) throw std::runtime_error("cannot encode a tile: " + std::string(CPLGetLastErrorMsg()));
  out.reset();
  vsi_l_offset length = 0;
  GByte* data = VSIGetMemFileBuffer(name.c_str(), &length, TRUE);
  if (!data) throw std::runtime_error("cannot read back an encoded tile");
  std::string bytes(reinterpret_cast<const char*>(data), static_cast<std::size_t>(length));
  CPLFree(data);
  return bytes;
}

}  // namespace skylit::app::tiles
