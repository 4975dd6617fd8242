#include "app/bench/bench_output.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace skylit::app::bench {
namespace {

std::string number(double v, const char* format) {
  if (!std::isfinite(v)) return "NA";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string preset_name(const BenchSetting& s) {
  return s.preset ? std::string(shading::quality_name(*s.preset)) : "";
}

constexpr const char* kTableFormat =
    "%-10s %5s %3s %3s %3s %2s %2s %2s %-7s %-8s %-6s %-5s %2s %2s %-8s %10s %10s %10s %10s %10s %9s %9s %9s\n";

}  // namespace

void print_table_header(std::ostream& out) {
  char buf[256];
  std::snprintf(buf, sizeof buf, kTableFormat, "scene", "size", "W", "kv", "o", "n", "N", "s", "wedge", "levels", "max",
                "hz", "K", "L", "preset", "ms_median", "ms_p10", "ms_p90", "sky_rmse", "sky_max", "shd_rmse", "shd_max",
                "shd_same");
  out << buf << std::flush;
}

void print_table_row(std::ostream& out, const BenchRow& r) {
  const BenchSetting& s = r.setting;
  char buf[256];
  std::snprintf(buf, sizeof buf, kTableFormat, r.scene.substr(0, 10).c_str(), r.size.c_str(),
                std::to_string(s.azimuths).c_str(), std::to_string(s.k_v).c_str(),
                number(s.level_offset, "%g").c_str(), std::to_string(s.sh_order).c_str(),
                std::to_string(s.nlp_order).c_str(), std::to_string(s.subsample).c_str(),
                std::string(wedge_name(s.wedge)).c_str(), std::string(horizon::level_sampling_name(s.levels)).c_str(),
                std::string(horizon::horizon_max_name(s.smooth_max)).c_str(),
                std::string(horizon::horizon_method_name(s.horizons)).c_str(), std::to_string(s.near_steps).c_str(),
                std::to_string(s.sweep_lines).c_str(), preset_name(s).c_str(),
                r.skipped ? "skipped" : number(r.frame_ms.median, "%.2f").c_str(),
                number(r.frame_ms.p10, "%.2f").c_str(), number(r.frame_ms.p90, "%.2f").c_str(),
                number(r.skyview.rmse, "%.5f").c_str(), number(r.skyview.max, "%.4f").c_str(),
                number(r.shaded.rmse, "%.3f").c_str(), number(r.shaded.max, "%.1f").c_str(),
                number(r.shaded_same_order.rmse, "%.3f").c_str());
  out << buf << std::flush;
}

std::string csv_text(const std::vector<BenchRow>& rows) {
  std::string text =
      "scene,size,backend,azimuths,k_v,level_offset,sh_order,nlp_order,subsample,wedge,levels,max,horizons,"
      "near_steps,sweep_lines,preset,clock,"
      "ms_median,ms_p10,ms_p90,wall_ms_median,skyview_rmse,skyview_max,shaded_rmse,shaded_max,"
      "shaded_same_order_rmse,shaded_same_order_max,status\n";
  for (const BenchRow& r : rows) {
    const BenchSetting& s = r.setting;
    text += r.scene + "," + r.size + "," + r.backend + "," + std::to_string(s.azimuths) + "," +
            std::to_string(s.k_v) + "," + number(s.level_offset, "%g") + "," + std::to_string(s.sh_order) + "," +
            std::to_string(s.nlp_order) + "," + std::to_string(s.subsample) + "," + std::string(wedge_name(s.wedge)) +
            "," + std::string(horizon::level_sampling_name(s.levels)) + "," +
            std::string(horizon::horizon_max_name(s.smooth_max)) + "," +
            std::string(horizon::horizon_method_name(s.horizons)) + "," + std::to_string(s.near_steps) + "," +
            std::to_string(s.sweep_lines) + "," + preset_name(s) + "," + r.clock + "," +
            number(r.frame_ms.median, "%.4f") + "," +
            number(r.frame_ms.p10, "%.4f") + "," + number(r.frame_ms.p90, "%.4f") + "," +
            number(r.wall_ms_median, "%.4f") + "," + number(r.skyview.rmse, "%.7g") + "," +
            number(r.skyview.max, "%.7g") + "," + number(r.shaded.rmse, "%.7g") + "," +
            number(r.shaded.max, "%.7g") + "," + number(r.shaded_same_order.rmse, "%.7g") + "," +
            number(r.shaded_same_order.max, "%.7g") + "," + (r.skipped ? "skipped" : "ok") + "\n";
  }
  return text;
}

}  // namespace skylit::app::bench
