#include "shading/products.h"

#include "shading/horizon/azimuth.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace skylit::shading {

std::string_view product_name(Product p) {
  switch (p) {
    case Product::Horizon: return "horizon";
    case Product::Svf: return "svf";
    case Product::Skyview: return "skyview";
    case Product::Shaded: return "shaded";
    case Product::Shadow: return "shadow";
    case Product::Irradiance: return "irradiance";
  }
  return "unknown";
}

namespace {
constexpr Product kProducts[] = {Product::Horizon, Product::Svf,    Product::Skyview,
                                 Product::Shaded,  Product::Shadow, Product::Irradiance};
}  // namespace

std::optional<Product> parse_product(std::string_view name) {
  for (Product p : kProducts)
    if (product_name(p) == name) return p;
  return std::nullopt;
}

std::string product_names() {
  std::string out;
  for (Product p : kProducts) out += (out.empty() ? "" : ", ") + std::string(product_name(p));
  return out;
}

void validate_subsample(const ProductOptions& options) {
  const int s = options.subsample;
  if (s != 1 && s != 2 && s != 4) throw std::invalid_argument("subsample must be 1, 2 or 4");
  if (s != 1 && options.exact) throw std::invalid_argument("subsample needs the multi-resolution march (not --exact)");
}

bool uses_lighting(Product product, const ProductOptions& options) {
  return product == Product::Shadow || product == Product::Irradiance ||
         (product == Product::Shaded && options.lighting.has_value());
}

double svf_from_horizon(const std::vector<double>& sigma) {
  double sum = 0.0;
  for (double s : sigma) sum += std::sin(std::max(s, 0.0));
  return 1.0 - sum / static_cast<double>(sigma.size());
}

double skyview_slice_integral(double lo, const glm::dvec3& n, double u_east, double u_north) {
  // n·ω(e) = a cos e + b sin e = R cos(e − δ): positive for e > δ − π/2 (b = n_z > 0
  // keeps δ + π/2 above the zenith). ∫ (a cos e + b sin e) cos e de = F(e) below.
  constexpr double kHalfPi = std::numbers::pi / 2;
  const double a = n.x * u_east + n.y * u_north, b = n.z;
  const double lower = std::max(lo, std::atan2(b, a) - kHalfPi);
  if (lower >= kHalfPi) return 0.0;
  auto F = [&](double e) { return a * (e / 2 + std::sin(2 * e) / 4) + b * std::sin(e) * std::sin(e) / 2; };
  return (F(kHalfPi) - F(lower)) / std::numbers::pi;
}

double skyview_from_horizon(const std::vector<double>& sigma, const glm::dvec3& normal) {
  const int w = static_cast<int>(sigma.size());
  double sum = 0.0;
  for (int k = 0; k < w; ++k) {
    const horizon::Heading u = horizon::heading_from_geographic(horizon::band_azimuth(k, w));
    // The uniform sky exists only above the horizontal.
    sum += skyview_slice_integral(std::max(sigma[k], 0.0), normal, u.east, u.north);
  }
  return sum * horizon::kTwoPi / w;
}

float srgb_code_value(double linear) {
  const double x = std::clamp(linear, 0.0, 1.0);
  const double encoded = x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
  return static_cast<float>(1.0 + std::round(254.0 * encoded));
}

}  // namespace skylit::shading
