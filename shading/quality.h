// Quality presets (`--quality fast|default|high`): named points on the speed/accuracy
// Pareto front that `skylit bench` measures (docs/quality-presets.md gives the front
// and why each preset sits where it does).
#pragma once

#include "shading/horizon/horizon_march.h"
#include "shading/products.h"

#include <optional>
#include <string_view>
#include <vector>

namespace skylit::shading {

enum class Quality { Fast, Default, High };

std::string_view quality_name(Quality q);  // "fast", "default", "high"
std::vector<Quality> all_qualities();      // fastest first
std::optional<Quality> parse_quality(std::string_view name);

// The quality knobs a preset sets: horizon azimuths W, pyramid levels per halving k_v,
// level offset o_v, how steps read heights, the horizon maximum (smooth or plain), how
// horizons are found (march or sweep) with the sweep's near steps K and lines per
// texel, SH order n and NLP order N of the shaded visibility.
struct QualitySettings {
  int azimuths;
  int k_v;
  double level_offset;
  horizon::LevelSampling levels;
  bool smooth_max;
  horizon::HorizonMethod horizons;
  int sweep_near_steps;
  int sweep_lines;
  int sh_order;
  int nlp_order;
};
QualitySettings quality_settings(Quality q);

// Overwrites only the knobs above; every other option (distance, curvature, threads,
// albedo, exposure, exact, …) is left as the caller set it.
void apply_settings(const QualitySettings& s, ProductOptions& options);
// apply_settings(quality_settings(q), options).
void apply_quality(Quality q, ProductOptions& options);

}  // namespace skylit::shading
