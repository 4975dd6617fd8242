#include "shading/blockers/cap_log_table.h"

#include "shading/sh/sh_basis.h"
#include "shading/sh/sh_exp_reference.h"
#include "shading/sh/zonal.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <utility>

namespace skylit::blockers {

CapLogTable::CapLogTable(int order, double epsilon, int entries)
    : order_(order), entries_(entries), values_(static_cast<std::size_t>(entries) * order) {
  sh::Vec zh(order), v(sh::num_coeffs(order), 0.0);
  for (int e = 0; e < entries; ++e) {
    const double s2 = static_cast<double>(e) / (entries - 1);
    sh::cap_zh(std::sqrt(1.0 - s2), zh);
    // The cap's visibility 1 − cap about +z, as a full SH vector (zonal: m = 0 only).
    for (int l = 0; l < order; ++l) v[sh::index(l, 0)] = (l == 0 ? sh::kSqrt4Pi : 0.0) - zh[l];
    const sh::Vec log_v = sh::log_product_algebra(v, epsilon);
    // No cap, V = 1: log* is exactly zero (the first linear piece starts from it).
    for (int l = 0; l < order; ++l)
      values_[static_cast<std::size_t>(e) * order + l] = e == 0 ? 0.0 : log_v[sh::index(l, 0)];
  }
}

void CapLogTable::log_zh(double s, std::span<double> out) const {
  const double x = std::clamp(s * s, 0.0, 1.0) * (entries_ - 1);
  const int e = std::min(static_cast<int>(x), entries_ - 2);
  const double t = x - e;
  for (int l = 0; l < order_; ++l)
    out[l] = (1.0 - t) * values_[static_cast<std::size_t>(e) * order_ + l] +
             t * values_[static_cast<std::size_t>(e + 1) * order_ + l];
}

const CapLogTable& cap_log_table(int order, double epsilon) {
  static std::mutex mutex;
  static std::map<std::pair<int, double>, std::unique_ptr<CapLogTable>> tables;
  const std::lock_guard lock(mutex);
  auto& t = tables[{order, epsilon}];
  if (!t) t = std::make_unique<CapLogTable>(order, epsilon);
  return *t;
}

}  // namespace skylit::blockers
