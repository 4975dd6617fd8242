#include "shading/quality_front.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace skylit::shading {
namespace {

constexpr std::string_view kHeader =
    "product,horizons,azimuths,kv,level_offset,levels,horizon_max,near_steps,sweep_lines,sh_order,nlp_order,"
    "subsample,wedge,relative_cost,error,label";
constexpr int kFields = 16;

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> f;
  std::stringstream s(line);
  std::string item;
  while (std::getline(s, item, ',')) f.push_back(item);
  return f;
}

std::string_view wedge_text(sh::WedgeInterpolation w) {
  return w == sh::WedgeInterpolation::BSpline ? "bspline" : "linear";
}

}  // namespace

std::string_view front_csv_header() { return kHeader; }

std::string front_csv_line(const FrontPoint& p) {
  const QualitySettings& s = p.settings;
  std::ostringstream o;
  o.precision(7);
  o << product_name(p.product) << ',' << horizon::horizon_method_name(s.horizons) << ',' << s.azimuths << ','
    << s.k_v << ',' << s.level_offset << ',' << horizon::level_sampling_name(s.levels) << ','
    << horizon::horizon_max_name(s.smooth_max) << ',' << s.sweep_near_steps << ',' << s.sweep_lines << ','
    << s.sh_order << ',' << s.nlp_order << ',' << p.subsample << ',' << wedge_text(p.wedge) << ','
    << p.relative_cost << ',' << p.error << ',' << p.label;
  return o.str();
}

std::vector<FrontPoint> parse_front(const std::string& text) {
  std::vector<FrontPoint> front;
  std::stringstream in(text);
  std::string line;
  int number = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    auto bad = [&](const std::string& why) {
      return std::runtime_error("quality front line " + std::to_string(number) + ": " + why);
    };
    if (!header) {
      if (line != kHeader) throw bad("expected the header '" + std::string(kHeader) + "'");
      header = true;
      continue;
    }
    const auto f = split(line);
    if (static_cast<int>(f.size()) != kFields) throw bad(std::to_string(kFields) + " fields expected");
    FrontPoint p;
    const auto product = parse_product(f[0]);
    const auto method = horizon::parse_horizon_method(f[1]);
    const auto levels = horizon::parse_level_sampling(f[5]);
    if (!product || !method || !levels) throw bad("unknown product, horizon method or level sampling");
    if (f[6] != horizon::horizon_max_name(true) && f[6] != horizon::horizon_max_name(false))
      throw bad("unknown horizon maximum '" + f[6] + "'");
    if (f[12] != "linear" && f[12] != "bspline") throw bad("unknown wedge '" + f[12] + "'");
    try {
      p.product = *product;
      p.settings = {std::stoi(f[2]), std::stoi(f[3]),  std::stod(f[4]),  *levels,          f[6] == horizon::horizon_max_name(true),
                    *method,         std::stoi(f[7]),  std::stoi(f[8]),  std::stoi(f[9]), std::stoi(f[10])};
      p.subsample = std::stoi(f[11]);
      p.wedge = f[12] == "bspline" ? sh::WedgeInterpolation::BSpline : sh::WedgeInterpolation::Linear;
      p.relative_cost = std::stod(f[13]);
      p.error = std::stod(f[14]);
    } catch (const std::logic_error&) {
      throw bad("a number does not parse");
    }
    if (!std::isfinite(p.relative_cost) || !std::isfinite(p.error)) throw bad("cost and error must be finite");
    p.label = f[15];
    front.push_back(p);
  }
  if (!header) throw std::runtime_error("quality front: no header line");
  return front;
}

std::vector<FrontPoint> load_front(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read the quality front '" + path + "'");
  std::stringstream text;
  text << in.rdbuf();
  return parse_front(text.str());
}

FrontChoice pick_setting(const std::vector<FrontPoint>& front, Product product, double max_error) {
  if (!(max_error > 0) || !std::isfinite(max_error))
    throw std::invalid_argument("the error target must be a finite number > 0");
  const FrontPoint* cheapest = nullptr;
  const FrontPoint* best = nullptr;
  for (const FrontPoint& p : front) {
    if (p.product != product) continue;
    if (!best || p.error < best->error || (p.error == best->error && p.relative_cost < best->relative_cost)) best = &p;
    if (p.error <= max_error &&
        (!cheapest || p.relative_cost < cheapest->relative_cost ||
         (p.relative_cost == cheapest->relative_cost && p.error < cheapest->error)))
      cheapest = &p;
  }
  if (!best)
    throw std::invalid_argument("the quality front has no " + std::string(product_name(product)) + " settings");
  return cheapest ? FrontChoice{*cheapest, true} : FrontChoice{*best, false};
}

void apply_front_point(const FrontPoint& p, ProductOptions& options) {
  apply_settings(p.settings, options);
  options.subsample = p.subsample;
  options.shaded.wedge = p.wedge;
}

}  // namespace skylit::shading
