// `skylit bench`: the quality settings it sweeps, how one setting is timed and
// how its products are compared with the brute-force ground truth.
//
// Swept (everything ProductOptions exposes that trades speed for accuracy):
// azimuths W, pyramid levels per halving k_v, level offset o_v, SH order n (with NLP
// order N = 2n, DESIGN.md step 4), horizon sub-sampling s, wedge interpolation, how
// steps read heights (horizon::LevelSampling), the smooth or plain horizon maximum,
// and how horizons are found (march or sweep, with the sweep's near steps K and lines
// per texel; horizon_sweep.h).
#pragma once

#include "shading/horizon/horizon_march.h"
#include "shading/products.h"
#include "shading/quality.h"
#include "shading/sh/wedge.h"
#include "terrain/height_field.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace skylit::app::bench {

struct BenchSetting {
  int azimuths = 0;        // W
  int k_v = 0;
  double level_offset = 0; // o_v
  int sh_order = 0;        // n
  int nlp_order = 0;       // N: 2n in the sweeps, the preset's own N for presets
  int subsample = 1;       // s: horizons marched at every s-th texel
  sh::WedgeInterpolation wedge = sh::WedgeInterpolation::Linear;
  horizon::LevelSampling levels = horizon::level_sampling(horizon::MarchOptions{});
  bool smooth_max = horizon::MarchOptions{}.smooth_max;
  // Sweep settings keep the march knobs above (k_v, o_v, levels, max) and s = 1 at the
  // defaults, march settings the sweep knobs: the sweep ignores the first, the march
  // the second, so no two settings compute the same horizons.
  horizon::HorizonMethod horizons = horizon::MarchOptions{}.method;
  int near_steps = horizon::MarchOptions{}.sweep_near_steps;  // K
  int sweep_lines = horizon::MarchOptions{}.sweep_lines;
  std::optional<shading::Quality> preset;  // the --quality preset this setting equals

  // The same horizons (skyview depends on nothing else).
  bool same_march(const BenchSetting& o) const {
    return azimuths == o.azimuths && k_v == o.k_v && level_offset == o.level_offset && subsample == o.subsample &&
           levels == o.levels && smooth_max == o.smooth_max && horizons == o.horizons &&
           near_steps == o.near_steps && sweep_lines == o.sweep_lines;
  }
  bool operator==(const BenchSetting& o) const {
    return same_march(o) && sh_order == o.sh_order && nlp_order == o.nlp_order && wedge == o.wedge;
  }
  // "W32 kv4 o3 n4", plus " s2" / " bspl" where not 1 / linear, the level sampling,
  // horizon maximum and method where not the library defaults (" bspline", " smooth",
  // " sweep", ...), and " K4 L2" for a sweep.
  std::string label() const;
};

// "linear" or "bspline", as `skylit shade --wedge` spells them.
std::string_view wedge_name(sh::WedgeInterpolation w);

// Names accepted by --sweep: "smoke" (the lowest, default and highest setting, for
// tests), "default" (one knob at a time around the default sweep and the default march,
// the march's pyramid knobs and s on the march only, four sweeps (K, lines) at the fast
// and default W, the two extreme corners and the presets: 32, minutes at 128² on 2
// cores), "full" (every combination of W, k_v, o_v, n, s and wedge, plus every march
// (W, k_v, o_v, levels, max) at the default n, s and wedge, plus the four sweeps crossed
// with W, n and wedge and every sweep (W, K, lines) at the default n and wedge, plus the
// presets: 945, for GPU machines). Settings equal to a preset carry it.
std::vector<std::string> sweep_names();
// Throws std::invalid_argument naming the valid sweeps.
std::vector<BenchSetting> sweep_settings(std::string_view name);

// The options of one setting: the library defaults with the swept fields replaced.
shading::ProductOptions options_for(const BenchSetting& s, unsigned threads);
// The brute-force ground truth: exact march, and the shaded product's visibility at
// the highest SH order, so that lower orders are charged for their band limit.
shading::ProductOptions truth_options(unsigned threads);

struct TimeStats {
  double median = 0, p10 = 0, p90 = 0;  // milliseconds
};
// Percentiles by linear interpolation between order statistics; samples not empty.
TimeStats time_stats(std::vector<double> samples_ms);

struct ErrorStats {
  double rmse = 0, max = 0;  // NaN when there is no ground truth
};
// Over texels where both are finite (nodata is NaN in both); NaN if none are.
ErrorStats error_stats(const shading::ProductBands& value, const shading::ProductBands& truth);

}  // namespace skylit::app::bench
