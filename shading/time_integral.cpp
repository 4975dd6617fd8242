#include "shading/time_integral.h"

#include "shading/sky/sky_model.h"

#include <stdexcept>

namespace skylit::shading {

std::vector<double> trapezoid_weights_hours(std::span<const sky::UtcTime> t) {
  std::vector<double> w(t.size(), 0.0);
  for (std::size_t k = 1; k < t.size(); ++k) {
    const double h = (t[k].unix_seconds - t[k - 1].unix_seconds) / 3600.0;
    if (!(h > 0.0)) throw std::invalid_argument("time series: the instants must strictly increase");
    w[k - 1] += 0.5 * h;
    w[k] += 0.5 * h;
  }
  return w;
}

bool sun_above_horizon(const sky::Sun& sun) { return sky::elevation_of(sun.direction) > 0.0; }

}  // namespace skylit::shading
