#include "app/shade/tinted_relief.h"

#include "app/shade/color_relief_cmd.h"
#include "shading/relief/color_relief.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace skylit::app::shade {

void parse_tint_blend(const std::string& text, TintArgs& out) {
  for (const auto& [name, blend] : {std::pair{std::string("multiply"), relief::TintBlend::Multiply},
                                    std::pair{std::string("soft-light"), relief::TintBlend::SoftLight}}) {
    if (text.rfind(name, 0) != 0) continue;
    out.blend = blend;
    out.weight = 1.0;
    if (text.size() == name.size()) return;
    if (text[name.size()] == ':') {
      const char* start = text.c_str() + name.size() + 1;
      char* end = nullptr;
      const double w = std::strtod(start, &end);
      if (end != start && *end == '\0' && w >= 0.0 && w <= 1.0) {
        out.weight = w;
        return;
      }
    }
  }
  throw std::invalid_argument("--tint-blend '" + text + "': expected multiply[:W] or soft-light[:W] (0 ≤ W ≤ 1)");
}

shading::ProductBands tint(const shading::ProductBands& shaded, const terrain::HeightField& field, const TintArgs& args) {
  relief::SourceInfo info;
  info.nodata = field.nodata;
  info.min_max = [&]() {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t k = 0; k < field.heights.size(); ++k)
      if (field.valid.empty() || field.valid[k]) lo = std::min(lo, double(field.heights[k])), hi = std::max(hi, double(field.heights[k]));
    return std::pair(lo, hi);
  };
  const relief::ColorTable table = relief::read_color_table(resolve_color_file(args.color), info);
  shading::ProductBands out;
  out.width = shaded.width;
  out.height = shaded.height;
  out.bands = 3;
  out.band_names = {"red", "green", "blue"};
  const std::size_t plane = static_cast<std::size_t>(out.width) * out.height;
  out.data.assign(3 * plane, std::numeric_limits<float>::quiet_NaN());
  for (std::size_t k = 0; k < plane; ++k) {
    const relief::Rgba c = relief::color_at(table, field.heights[k], relief::ColorSelection::Interpolate);
    for (int b = 0; b < 3; ++b) {
      const float v = shaded.data[(shaded.bands == 3 ? b : 0) * plane + k];
      if (std::isnan(v)) continue;
      const double shade = (v - 1.0) / 254.0;  // the relief as displayed: code values 1…255 (products.h)
      const double colour = c[b] / 255.0;
      const double blended = args.blend == relief::TintBlend::Multiply
                                 ? relief::multiply_mix(colour, shade, args.weight)
                                 : relief::soft_light_mix(colour, shade, args.weight);
      out.data[b * plane + k] = static_cast<float>(1.0 + std::round(254.0 * std::clamp(blended, 0.0, 1.0)));
    }
  }
  return out;
}

}  // namespace skylit::app::shade
