#include "app/shade/shade_output.h"

#include "terrain/raster_writer.h"

#include <gdal_priv.h>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

namespace skylit::app::shade {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string canonical_format(const std::string& f) {
  const std::string l = lower(f);
  if (l == "gtiff" || l == "tif" || l == "tiff" || l == "geotiff") return "GTiff";
  if (l == "cog") return "COG";
  if (l == "png") return "PNG";
  // Any other GDAL raster driver that can Create or CreateCopy (the writer copies from
  // an in-memory raster for copy-only ones), as gdaldem -of.
  GDALAllRegister();
  GDALDriver* d = GetGDALDriverManager()->GetDriverByName(f.c_str());
  if (!d || !d->GetMetadataItem(GDAL_DCAP_RASTER))
    throw std::invalid_argument("unknown output format '" + f + "' (a GDAL raster driver name: GTiff, COG, PNG, ...)");
  if (!d->GetMetadataItem(GDAL_DCAP_CREATE) && !d->GetMetadataItem(GDAL_DCAP_CREATECOPY))
    throw std::invalid_argument("GDAL's " + f + " driver cannot write rasters");
  return d->GetDescription();
}

std::string format_from_extension(const std::filesystem::path& p) {
  const std::string ext = lower(p.extension().string());
  if (ext == ".png") return "PNG";
  if (ext == ".tif" || ext == ".tiff") return "GTiff";
  throw std::invalid_argument("cannot tell the output format from '" + p.filename().string() +
                              "': use a .tif or .png name, or -of GTiff|COG|PNG");
}

}  // namespace

OutputSpec resolve_output(const std::string& path, const std::string& format, shading::Product product,
                          const std::vector<std::string>& creation_options, bool overwrite) {
  namespace fs = std::filesystem;
  if (path.empty()) throw std::invalid_argument("no output path given (-o)");
  OutputSpec spec;
  spec.path = path;
  spec.format = format.empty() ? format_from_extension(path) : canonical_format(format);
  spec.creation_options = creation_options;
  spec.eight_bit = shading::traits(product).eight_bit;
  spec.overwrite = overwrite;
  for (const auto& co : creation_options)
    if (co.find('=') == std::string::npos || co.front() == '=')
      throw std::invalid_argument("creation option '" + co + "' is not NAME=VALUE");
  if (spec.format == "PNG" && !spec.eight_bit)
    throw std::invalid_argument("PNG cannot hold the Float32 '" + std::string(shading::product_name(product)) +
                                "' product: write a .tif (GTiff or COG)");
  const fs::path p(path);
  std::error_code ec;
  if (fs::is_directory(p, ec)) throw std::invalid_argument("output '" + path + "' is a directory");
  if (fs::exists(p, ec) && !overwrite)
    throw std::invalid_argument("output '" + path + "' exists; pass --overwrite to replace it");
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  if (!fs::is_directory(dir, ec)) throw std::invalid_argument("output folder '" + dir.string() + "' does not exist");
  if (access(dir.c_str(), W_OK) != 0) throw std::invalid_argument("output folder '" + dir.string() + "' is not writable");
  return spec;
}

void write_product(const OutputSpec& spec, const terrain::HeightField& field, const shading::ProductBands& bands) {
  terrain::RasterWriteOptions opt;
  opt.format = spec.format;
  opt.creation_options = spec.creation_options;
  opt.band_descriptions = bands.band_names;
  opt.overwrite = spec.overwrite;
  if (spec.eight_bit) {
    opt.nodata = kByteNodata;
    terrain::write_raster(spec.path, field.georef, bands.width, bands.height, bands.bands,
                          std::span<const std::uint8_t>(byte_samples(bands.data)), opt);
  } else {
    opt.nodata = kFloatNodata;
    terrain::write_raster(spec.path, field.georef, bands.width, bands.height, bands.bands,
                          std::span<const float>(float_samples(bands.data)), opt);
  }
}

std::vector<std::uint8_t> byte_samples(std::span<const float> values) {
  std::vector<std::uint8_t> bytes(values.size());
  for (std::size_t k = 0; k < bytes.size(); ++k) {
    const float v = values[k];
    bytes[k] = std::isfinite(v) ? static_cast<std::uint8_t>(std::clamp(std::lround(v), 1L, 255L))
                                : static_cast<std::uint8_t>(kByteNodata);
  }
  return bytes;
}

std::vector<float> float_samples(std::span<const float> values) {
  std::vector<float> data(values.begin(), values.end());
  for (float& v : data)
    if (!std::isfinite(v)) v = static_cast<float>(kFloatNodata);
  return data;
}

}  // namespace skylit::app::shade
