#include "app/shade/max_error.h"

#include "shading/quality_front.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace skylit::app::shade {
namespace {

// The knobs a front point sets, as the command line names them.
const char* const kKnobs[] = {"--quality", "--azimuths", "--kv",        "--level-offset", "--levels",
                              "--horizon-max", "--horizons", "--near-steps", "--sweep-lines", "--sh-order",
                              "--nlp-order", "--subsample", "--wedge"};

std::string unit(shading::Product p) {
  return p == shading::Product::Shaded ? " 8-bit code values RMSE" : " RMSE (fraction of the sky)";
}

}  // namespace

std::string quality_front_path() {
  if (const char* env = std::getenv("SKYLIT_QUALITY_FRONT"); env && *env) return env;
  return std::string(SKYLIT_SOURCE_DIR) + "/data/quality/front.csv";
}

std::string apply_max_error(double max_error, const std::string& product, const CLI::App& cmd,
                            shading::ProductOptions& options) {
  if (!(max_error > 0) || !std::isfinite(max_error))
    throw std::invalid_argument("--max-error must be a finite number > 0");
  const auto p = shading::parse_product(product);
  if (!p || (*p != shading::Product::Svf && *p != shading::Product::Skyview && *p != shading::Product::Shaded))
    throw std::invalid_argument("--max-error applies to -p svf, skyview or shaded (not " + product + ")");
  if (options.exact) throw std::invalid_argument("--max-error picks a setting; --exact is the brute force: give one");
  std::vector<shading::FrontPoint> front;
  try {
    front = shading::load_front(quality_front_path());
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument("--max-error: " + std::string(e.what()));
  }
  const shading::FrontChoice c = shading::pick_setting(front, *p, max_error);
  shading::apply_front_point(c.point, options);
  std::ostringstream note;
  if (c.met)
    note << "--max-error " << max_error << ": " << c.point.label << " (front error " << c.point.error << unit(*p)
         << ", cost " << c.point.relative_cost << "x the default)";
  else
    note << "--max-error " << max_error << ": no setting on the front meets it; the most accurate, "
         << c.point.label << " (front error " << c.point.error << unit(*p) << ")";
  std::string given;
  for (const char* k : kKnobs)
    if (cmd.count(k)) given += std::string(given.empty() ? "" : ", ") + k;
  if (!given.empty()) note << "\nskylit: note: " << given << " given explicitly: they win over --max-error's choice";
  return note.str();
}

}  // namespace skylit::app::shade
