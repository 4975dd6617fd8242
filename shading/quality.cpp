#include "shading/quality.h"

namespace skylit::shading {
namespace {

// The library defaults (MarchOptions, ShadedOptions) are the Default preset, so the
// two can never drift apart.
QualitySettings library_defaults() {
  const ProductOptions d;
  return {d.march.azimuths,   d.march.k_v,    d.march.level_offset,     horizon::level_sampling(d.march),
          d.march.smooth_max, d.march.method, d.march.sweep_near_steps, d.march.sweep_lines,
          d.shaded.sh_order,  d.shaded.nlp_order};
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
  // Chosen from the GPU front (llvmpipe, 256² and 512², docs/quality-presets.md) and the
  // real-DEM accuracy (docs/accuracy.md); an NVIDIA front is still to be measured with
  // `skylit bench --backend gpu`. Each preset changes one knob of the march and of the
  // sweep (whichever runs):
  QualitySettings s = library_defaults();
  switch (q) {
    case Quality::Fast:
      s.azimuths = 16;  // the knee: half the time; K 2 instead of 4 measured no faster at W 16
      break;
    case Quality::Default: break;
    case Quality::High:
      s.k_v = 8;  // march: the best skyview (−25 % RMSE) for 1.6× the CPU; more W adds nothing
      s.sweep_near_steps = 8;  // sweep: at the azimuth-sampling floor of W 32 (docs/accuracy.md)
      s.sweep_lines = 3;
      break;
  }
  return s;
}

void apply_quality(Quality q, ProductOptions& options) { apply_settings(quality_settings(q), options); }

void apply_settings(const QualitySettings& s, ProductOptions& options) {
  options.march.azimuths = s.azimuths;
  options.march.k_v = s.k_v;
  options.march.level_offset = s.level_offset;
  horizon::set_level_sampling(options.march, s.levels);
  options.march.smooth_max = s.smooth_max;
  options.march.method = s.horizons;
  options.march.sweep_near_steps = s.sweep_near_steps;
  options.march.sweep_lines = s.sweep_lines;
  options.shaded.sh_order = s.sh_order;
  options.shaded.nlp_order = s.nlp_order;
}

}  // namespace skylit::shading
