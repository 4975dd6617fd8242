#include "shading/quality.h"

namespace skylit::shading {
namespace {

// The library defaults (MarchOptions, ShadedOptions) are the Default preset, so the
// two can never drift apart.
QualitySettings library_defaults() {
  const ProductOptions d;
  return {d.march.azimuths, d.march.k_v, d.march.level_offset, d.shaded.sh_order, d.shaded.nlp_order};
}

}  // namespace

std::string_view quality_name(Quality q) {
  switch (q) {
    case Quality::Fast: return "fast";
    case Quality::Default: return "default";
    case Quality::High: return "high";
  }
  return "unknown";
}

std::vector<Quality> all_qualities() { return {Quality::Fast, Quality::Default, Quality::High}; }

std::optional<Quality> parse_quality(std::string_view name) {
  for (Quality q : all_qualities())
    if (quality_name(q) == name) return q;
  return std::nullopt;
}

QualitySettings quality_settings(Quality q) {
  // Chosen from the front measured on the CPU reference at 128² and 256² and confirmed
  // on the GPU front (llvmpipe, 256²; docs/quality-presets.md); an NVIDIA front is still
  // to be measured with `skylit bench --backend gpu`.
  // Each preset changes one knob of the defaults:
  QualitySettings s = library_defaults();
  switch (q) {
    case Quality::Fast:
      s.azimuths = 16;  // the knee: half the march, +7–12 % shaded RMSE, same skyview error
      break;
    case Quality::Default: break;
    case Quality::High:
      s.k_v = 8;  // the best skyview (−25 % RMSE) for 1.6× the CPU; more W adds nothing
      break;
  }
  return s;
}

void apply_quality(Quality q, ProductOptions& options) {
  const QualitySettings s = quality_settings(q);
  options.march.azimuths = s.azimuths;
  options.march.k_v = s.k_v;
  options.march.level_offset = s.level_offset;
  options.shaded.sh_order = s.sh_order;
  options.shaded.nlp_order = s.nlp_order;
}

}  // namespace skylit::shading
