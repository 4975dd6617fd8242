// The measured speed/error front (data/quality/front.csv, made by `skylit bench
// --front`): per product, settings with their relative cost and worst error over the
// bench scenes; and the cheapest setting meeting an error target.
//
// Error: RMSE against the brute-force truth, in the product's own unit: svf and
// skyview as fractions of the sky (0…1), shaded in 8-bit sRGB code values (uniform
// sky, no sun). Cost: frame time over that of the default preset on the same scene.
#pragma once

#include "shading/products.h"
#include "shading/quality.h"
#include "shading/sh/wedge.h"

#include <string>
#include <string_view>
#include <vector>

namespace skylit::shading {

struct FrontPoint {
  Product product = Product::Shaded;
  QualitySettings settings{};
  int subsample = 1;
  sh::WedgeInterpolation wedge = sh::WedgeInterpolation::Linear;
  double relative_cost = 0;
  double error = 0;
  std::string label;  // the bench's name of the setting
};

// The CSV's header line (front_csv_line writes the rows under it).
std::string_view front_csv_header();
std::string front_csv_line(const FrontPoint& p);
// Lines starting with '#' are comments; throws std::runtime_error naming the line.
std::vector<FrontPoint> parse_front(const std::string& text);
std::vector<FrontPoint> load_front(const std::string& path);

struct FrontChoice {
  FrontPoint point;
  bool met = false;  // false: no point of the product meets the target; point is the most accurate
};
// The cheapest point of `product` with error ≤ max_error (ties: the lower error, then
// the first); when none meets it, the lowest error (ties: the cheaper). Throws
// std::invalid_argument when max_error is not > 0 or the front has no such product.
FrontChoice pick_setting(const std::vector<FrontPoint>& front, Product product, double max_error);

// Overwrites the knobs the point sets (those of apply_quality, subsample and wedge).
void apply_front_point(const FrontPoint& p, ProductOptions& options);

}  // namespace skylit::shading
