// `skylit bench`: the quality settings it sweeps, how one setting is timed and
// how its products are compared with the brute-force ground truth.
//
// Swept (everything ProductOptions exposes that trades speed for accuracy):
// azimuths W, pyramid levels per halving k_v, level offset o_v and SH order n
// (with NLP order N = 2n, DESIGN.md step 4). Wedge interpolation and
// sub-sampling are not options of ProductOptions yet, so they are not swept.
#pragma once

#include "shading/products.h"
#include "shading/quality.h"
#include "terrain/height_field.h"

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace skylit::app {

struct BenchSetting {
  int azimuths = 0;        // W
  int k_v = 0;
  double level_offset = 0; // o_v
  int sh_order = 0;        // n
  int nlp_order = 0;       // N: 2n in the sweeps, the preset's own N for presets
  std::optional<shading::Quality> preset;  // the --quality preset this setting equals

  bool same_march(const BenchSetting& o) const {
    return azimuths == o.azimuths && k_v == o.k_v && level_offset == o.level_offset;
  }
  bool operator==(const BenchSetting& o) const {
    return same_march(o) && sh_order == o.sh_order && nlp_order == o.nlp_order;
  }
  std::string label() const;  // "W32 kv4 o3 n4"
};

// Names accepted by --sweep: "smoke" (the lowest, default and highest setting, for
// tests), "default" (one knob at a time around the library defaults, the two extreme
// corners and the presets: minutes at 128² on 2 cores), "full" (every combination
// plus the presets: 108+, for GPU machines). Settings equal to a preset carry it.
std::vector<std::string> sweep_names();
// Throws std::invalid_argument naming the valid sweeps.
std::vector<BenchSetting> sweep_settings(std::string_view name);

// The options of one setting: the library defaults with the swept fields replaced.
shading::ProductOptions options_for(const BenchSetting& s, unsigned threads);
// The brute-force ground truth: exact march, and the shaded product's visibility at
// the highest SH order, so that lower orders are charged for their band limit.
shading::ProductOptions truth_options(unsigned threads);

// Where frame times come from. "wall" times compute_with_backend from the call to
// its return; "cpu" counts the process's CPU time over all threads instead (robust
// on a shared machine, where wall time depends on who else runs). A backend that can
// time its own GPU work (GL_TIME_ELAPSED, gpu/timer.h) implements this interface and
// reports device milliseconds as "gpu".
class TimingSource {
 public:
  virtual ~TimingSource() = default;
  virtual std::string_view clock() const = 0;  // the CSV's `clock` column: "wall", "gpu"
  // Computes one product; `ms` receives the time of that one computation.
  virtual shading::ProductBands compute(const terrain::HeightField& field, shading::Product product,
                                        const shading::ProductOptions& options, double& ms) = 0;
};

inline constexpr std::string_view kWallClock = "wall", kCpuClock = "cpu";
std::vector<std::string> clock_names();  // kWallClock (the default), kCpuClock
// A source over compute_with_backend(backend, …). Throws std::invalid_argument for a
// backend or clock name it does not know.
std::unique_ptr<TimingSource> make_timing_source(const std::string& backend, const std::string& clock);

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

}  // namespace skylit::app
