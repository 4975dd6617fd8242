// Products summed over the frames of a time series (time_series.h, time_integral.h):
// what r.sun's mode 2, SAGA's Potential Incoming Solar Radiation and whitebox's
// TimeInDaylight give.
//
//   insolation (Wh/m²): Σ_k w_k·E_k, E_k the `irradiance` frame at t_k (sky + sun);
//   sun-hours  (h):     Σ_k w_k·s_k, s_k the `shadow` frame (visible fraction of the
//                       solar disc) while the sun is above the horizon, else 0;
// w_k the trapezoid weights of the instants (hours). Nodata texels stay NaN.
#pragma once

#include "shading/lighting.h"
#include "shading/products.h"
#include "shading/sky/time_utc.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace skylit::shading {

enum class SummedProduct { Insolation, SunHours };

std::string_view summed_product_name(SummedProduct p);  // "insolation", "sun-hours"
std::optional<SummedProduct> parse_summed_product(std::string_view name);
std::string_view summed_product_unit(SummedProduct p);  // "Wh/m2", "h"
// The per-frame product that is summed: irradiance or shadow.
Product frame_product(SummedProduct p);

class SeriesSum {
 public:
  // Throws std::invalid_argument unless the instants strictly increase.
  SeriesSum(SummedProduct product, std::span<const sky::UtcTime> instants, int width, int height);
  // Whether frame k has to be rendered at all (sun hours: not while the sun is down).
  bool needs_frame(int k, const Lighting& lighting) const;
  // Adds frame k (a `frame_product` raster of the field's size).
  void add(int k, const ProductBands& frame);
  // Nodata: texels that any frame marked NaN; without any frame, `valid` says which.
  ProductBands result(std::span<const std::uint8_t> valid) const;

 private:
  SummedProduct product_;
  std::vector<double> weights_;
  int width_, height_;
  std::vector<double> sum_;
  std::vector<std::uint8_t> nodata_;
};

}  // namespace skylit::shading
