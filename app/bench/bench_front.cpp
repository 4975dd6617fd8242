#include "app/bench/bench_front.h"

#include "shading/quality_front.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>

namespace skylit::app::bench {
namespace {

using shading::Product;

// "model name" and "flags" of the first CPU, for the file's header.
std::string cpu_line(const std::string& key) {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(key, 0) == 0) {
      const auto colon = line.find(':');
      return colon == std::string::npos ? line : line.substr(std::min(colon + 2, line.size()));
    }
  return "unknown";
}

shading::FrontPoint point_of(const BenchSetting& s, Product product) {
  shading::FrontPoint p;
  p.product = product;
  p.settings = {s.azimuths, s.k_v, s.level_offset, s.levels, s.smooth_max, s.horizons, s.near_steps, s.sweep_lines,
                s.sh_order, s.nlp_order};
  p.subsample = s.subsample;
  p.wedge = s.wedge;
  p.label = s.label();
  return p;
}

double product_ms(const BenchRow& r, Product p) {
  return p == Product::Svf ? r.svf_ms : p == Product::Skyview ? r.skyview_ms : r.frame_ms.median;
}
double product_error(const BenchRow& r, Product p) {
  return p == Product::Svf ? r.svf.rmse : p == Product::Skyview ? r.skyview.rmse : r.shaded.rmse;
}

}  // namespace

std::string front_csv_text(const std::vector<BenchRow>& rows, const std::string& how_made) {
  std::set<std::string> scenes;
  std::string text = "# skylit quality front: " + how_made + "\n# machine: " + cpu_line("model name") +
                     "\n# cpu flags: " + cpu_line("flags") + "\n";
  for (const BenchRow& r : rows) scenes.insert(r.scene + " " + r.size);
  text += "# scenes:";
  for (const auto& s : scenes) text += " " + s + ";";
  text += "\n# error: worst RMSE over the scenes (svf, skyview: fraction of the sky; shaded: 8-bit code values, "
          "uniform sky); relative_cost: time over the default preset's on the same scene, mean over scenes\n";
  text += std::string(shading::front_csv_header()) + "\n";
  for (Product product : {Product::Svf, Product::Skyview, Product::Shaded}) {
    // Each scene's default-preset time.
    std::map<std::string, double> base;
    for (const BenchRow& r : rows)
      if (!r.skipped && r.setting.preset == shading::Quality::Default) base[r.scene + r.size] = product_ms(r, product);
    std::vector<std::pair<BenchSetting, shading::FrontPoint>> points;
    std::vector<int> counts;
    for (const BenchRow& r : rows) {
      const double err = product_error(r, product), ms = product_ms(r, product);
      const auto b = base.find(r.scene + r.size);
      if (r.skipped || !std::isfinite(err) || !std::isfinite(ms) || b == base.end() || !(b->second > 0)) continue;
      auto it = std::find_if(points.begin(), points.end(), [&](const auto& e) {
        // svf and skyview depend on the horizons alone: one point per march.
        return product == Product::Shaded ? e.first == r.setting : e.first.same_march(r.setting);
      });
      if (it == points.end()) {
        points.emplace_back(r.setting, point_of(r.setting, product));
        counts.push_back(0);
        it = points.end() - 1;
      }
      auto& p = it->second;
      const auto k = static_cast<std::size_t>(it - points.begin());
      p.relative_cost += ms / b->second;
      p.error = std::max(p.error, err);
      ++counts[k];
    }
    for (std::size_t k = 0; k < points.size(); ++k) points[k].second.relative_cost /= counts[k];
    for (const auto& [setting, p] : points) {
      const bool beaten = std::any_of(points.begin(), points.end(), [&](const auto& e) {
        const auto& q = e.second;
        return q.relative_cost <= p.relative_cost && q.error <= p.error &&
               (q.relative_cost < p.relative_cost || q.error < p.error);
      });
      if (!beaten) text += shading::front_csv_line(p) + "\n";
    }
  }
  return text;
}

}  // namespace skylit::app::bench
