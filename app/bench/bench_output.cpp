#include "app/bench/bench_output.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

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

std::string temp_name(const std::string& path) { return path + ".tmp-" + std::to_string(::getpid()); }

[[noreturn]] void fail(const std::string& what, const std::string& path, const std::string& reason) {
  throw std::runtime_error("cannot write " + what + " '" + path + "': " + reason);
}

// Writes `text` to `file`; returns why it failed ("" on success), leaving no file then.
std::string write_file(const std::string& file, const std::string& text) {
  errno = 0;
  std::ofstream f(file, std::ios::binary | std::ios::trunc);
  if (!f) return errno ? std::strerror(errno) : "cannot open";
  f << text;
  f.close();
  if (f) return "";
  std::error_code ignored;
  std::filesystem::remove(file, ignored);
  return "write failed";
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

void check_writable(const std::string& path, const std::string& what) {
  if (path.empty()) fail(what, path, "empty path");
  if (std::filesystem::is_directory(path)) fail(what, path, "is a directory");
  const std::string probe = temp_name(path);
  if (const std::string why = write_file(probe, ""); !why.empty()) fail(what, path, why);
  std::error_code ignored;
  std::filesystem::remove(probe, ignored);
}

void write_text_atomically(const std::string& path, const std::string& text, const std::string& what) {
  const std::string temp = temp_name(path);
  if (const std::string why = write_file(temp, text); !why.empty()) fail(what, path, why);
  std::error_code ec;
  std::filesystem::rename(temp, path, ec);
  if (ec) {
    const std::string why = ec.message();
    std::filesystem::remove(temp, ec);
    fail(what, path, why);
  }
}

}  // namespace skylit::app::bench
