// The plot of `skylit bench --plot`: error against time per frame (log axis), one
// row of panels per scene with ground truth (shaded RMSE | skyview RMSE), every
// setting as a point and the Pareto front as a polyline. Plain SVG 1.1, written
// by hand (no plotting dependency).
#pragma once

#include "app/bench/bench_run.h"

#include <cstddef>
#include <string>
#include <vector>

namespace skylit::app::bench {

struct PlotPoint {
  double ms = 0;     // time per frame (> 0)
  double error = 0;  // finite
};

// Indices of the points no other point beats in both time and error (ties: the
// faster one, then the first), fastest first: the error falls along the front.
std::vector<std::size_t> pareto_front(const std::vector<PlotPoint>& points);

// A complete SVG document; scenes without ground truth are named in a note.
std::string pareto_svg(const std::vector<BenchRow>& rows);

}  // namespace skylit::app::bench
