// `skylit bench`, one scene at a time: the ground truth once, then every setting of
// the sweep timed (median of --runs after --warmup) and compared with the truth.
#pragma once

#include "app/bench/bench_sweep.h"
#include "app/bench/bench_timing.h"

#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace skylit::app::bench {

struct BenchScene {
  std::string name;  // "synthetic" or the DEM's file name
  terrain::HeightField field;
  std::string size() const;  // "512", or "640x480" when not square
};

// The oracle of "exact" settings (DESIGN.md "Backends"); a GPU backend is faster.
inline constexpr std::string_view kOracleBackend = "reference";

struct BenchConfig {
  int runs = 20;
  int warmup = 3;
  unsigned threads = 0;
  int truth_max_size = 512;  // no ground truth for scenes with a side above this
  std::string truth_backend{kOracleBackend};  // computes the ground truth
};

// One line of the table / CSV. The time is that of the `shaded` product, the frame
// the renderer draws (its horizon march is the same as skyview's and dominates);
// errors are NaN without ground truth. A setting the backend lacks is skipped: its
// times and errors are NaN and `skipped` says why.
struct BenchRow {
  std::string scene, size, backend, clock;
  BenchSetting setting;
  TimeStats frame_ms;
  double wall_ms_median = 0;  // wall clock of the whole call (read-back, CPU stages included)
  ErrorStats skyview, shaded;
  std::optional<std::string> skipped;
  // shaded against a truth of the setting's own SH order, NLP order and wedge (exact
  // horizons): the horizons' error without the band limit that `shaded` charges.
  ErrorStats shaded_same_order{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  // svf against its truth, and one call of svf and skyview on the host clock (for the front).
  ErrorStats svf{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  double svf_ms = std::numeric_limits<double>::quiet_NaN(), skyview_ms = std::numeric_limits<double>::quiet_NaN();
};

// Seconds the brute-force truth (skyview + shaded) would take on the reference
// backend for a w × h scene: scaled as size³ from `measured` (side, seconds) when a
// truth was computed in this run, else from the single-core figure of
// docs/performance.md spread over `threads` workers (0 = all cores).
double estimate_truth_seconds(int width, int height, unsigned threads,
                              const std::optional<std::pair<int, double>>& measured);

using RowCallback = std::function<void(const BenchRow&)>;
using NoteCallback = std::function<void(const std::string&)>;  // one-line notes for stderr

// `timing` times the settings on its backend; `truth` computes the ground truth on
// config.truth_backend; `measured_truth` carries the calibration of
// estimate_truth_seconds from scene to scene.
std::vector<BenchRow> run_scene(const BenchScene& scene, const std::vector<BenchSetting>& settings,
                                const BenchConfig& config, TimingSource& timing, TimingSource& truth,
                                std::optional<std::pair<int, double>>& measured_truth,
                                const RowCallback& on_row, const NoteCallback& note);

}  // namespace skylit::app::bench
