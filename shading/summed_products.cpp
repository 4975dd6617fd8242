#include "shading/summed_products.h"

#include "shading/time_integral.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace skylit::shading {

std::string_view summed_product_name(SummedProduct p) {
  return p == SummedProduct::Insolation ? "insolation" : "sun-hours";
}

std::optional<SummedProduct> parse_summed_product(std::string_view name) {
  for (SummedProduct p : {SummedProduct::Insolation, SummedProduct::SunHours})
    if (summed_product_name(p) == name) return p;
  return std::nullopt;
}

std::string_view summed_product_unit(SummedProduct p) { return p == SummedProduct::Insolation ? "Wh/m2" : "h"; }

Product frame_product(SummedProduct p) { return p == SummedProduct::Insolation ? Product::Irradiance : Product::Shadow; }

SeriesSum::SeriesSum(SummedProduct product, std::span<const sky::UtcTime> instants, int width, int height)
    : product_(product), weights_(trapezoid_weights_hours(instants)), width_(width), height_(height),
      sum_(static_cast<std::size_t>(width) * height, 0.0), nodata_(sum_.size(), 0) {}

bool SeriesSum::needs_frame(int k, const Lighting& lighting) const {
  if (weights_[k] == 0.0) return false;  // a single instant: no interval to sum over
  return product_ == SummedProduct::Insolation || sun_above_horizon(lighting.sun);
}

void SeriesSum::add(int k, const ProductBands& frame) {
  if (frame.width != width_ || frame.height != height_ || frame.bands != 1)
    throw std::invalid_argument("SeriesSum::add: a frame of another size");
  const double w = weights_[k];
  for (std::size_t t = 0; t < sum_.size(); ++t) {
    const float v = frame.data[t];
    if (std::isnan(v))
      nodata_[t] = 1;
    else
      sum_[t] += w * v;
  }
}

ProductBands SeriesSum::result(std::span<const std::uint8_t> valid) const {
  ProductBands out{width_, height_, 1, std::vector<float>(sum_.size()), {std::string(summed_product_name(product_))}};
  for (std::size_t t = 0; t < sum_.size(); ++t)
    out.data[t] = nodata_[t] || (t < valid.size() && !valid[t]) ? std::numeric_limits<float>::quiet_NaN()
                                                                  : static_cast<float>(sum_[t]);
  return out;
}

}  // namespace skylit::shading
