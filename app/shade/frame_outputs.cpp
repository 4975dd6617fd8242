#include "app/shade/frame_outputs.h"

#include "shading/time_series.h"

#include <stdexcept>

namespace skylit::app::shade {

FrameOutputs resolve_frame_outputs(const std::string& path, const std::string& format, shading::Product product,
                                   const std::vector<std::string>& creation_options, bool overwrite, int frames,
                                   std::size_t bytes_per_frame, std::size_t max_bytes) {
  FrameOutputs out;
  out.per_frame = frame_pattern(path).has_value();
  if (out.per_frame) {
    for (int k = 0; k < frames; ++k)
      out.files.push_back(resolve_output(frame_path(path, k), format, product, creation_options, overwrite));
    if (frames > 1 && out.files[0].path == out.files[1].path)
      throw std::invalid_argument("output '" + path + "' names every frame alike");
    return out;
  }
  OutputSpec spec = resolve_output(path, format, product, creation_options, overwrite);
  if (frames > 1 && spec.format != "GTiff" && spec.format != "COG")
    throw std::invalid_argument("output '" + path + "': " + std::to_string(frames) + " frames need a %d in the name " +
                                "(frames/" + std::string(shading::product_name(product)) +
                                "_%04d.png: one file per frame) or a .tif (one band per time)");
  if (bytes_per_frame * static_cast<std::size_t>(frames) > max_bytes)
    throw std::invalid_argument("output '" + path + "': " + std::to_string(frames) + " frames of " +
                                std::to_string(bytes_per_frame >> 20) + " MiB are too many for one multi-band file; " +
                                "put a %d in the name for one file per frame");
  out.files.push_back(std::move(spec));
  return out;
}

std::vector<std::string> frame_band_names(const shading::ProductBands& frame, sky::UtcTime t) {
  const std::string when = shading::format_instant(t);
  if (frame.bands == 1) return {when};
  std::vector<std::string> names;
  for (const std::string& b : frame.band_names) names.push_back(when + " " + b);
  return names;
}

}  // namespace skylit::app::shade
