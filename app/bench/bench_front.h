// `skylit bench --front FILE`: the rows of all scenes reduced to the speed/error front
// that `skylit shade --max-error` picks from (shading/quality_front.h).
#pragma once

#include "app/bench/bench_run.h"

#include <string>
#include <vector>

namespace skylit::app::bench {

// Per product (svf, skyview, shaded) and setting: cost relative to the default preset
// on the same scene, averaged over scenes; error the worst RMSE over scenes; only
// the points no other point beats on both. Rows without truth or skipped are left out.
// The text starts with '#' lines naming the scenes and the machine (/proc/cpuinfo).
std::string front_csv_text(const std::vector<BenchRow>& rows, const std::string& how_made);

}  // namespace skylit::app::bench
