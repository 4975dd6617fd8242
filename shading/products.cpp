#include "shading/products.h"

#include "shading/horizon/azimuth.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

namespace skylit::shading {

namespace {

// One row per product, in the enum's order.
constexpr ProductTraits kTraits[] = {
    {.product = Product::Horizon, .name = "horizon", .band_per_azimuth = true},
    {.product = Product::Svf, .name = "svf"},
    {.product = Product::Skyview, .name = "skyview", .blocked = true},
    {.product = Product::Shaded, .name = "shaded", .rgb_when_colour = true, .needs_visibility = true, .lit = true,
     .eight_bit = true, .blocked = true},
    {.product = Product::Shadow, .name = "shadow", .lit = true, .needs_sun = true, .sun_only = true, .blocked = true},
    {.product = Product::Irradiance, .name = "irradiance", .needs_visibility = true, .lit = true, .needs_sun = true, .blocked = true},
    {.product = Product::Hillshade, .name = "hillshade", .eight_bit = true, .local = true},
};

constexpr bool in_enum_order() {
  for (std::size_t i = 0; i < std::size(kTraits); ++i)
    if (static_cast<std::size_t>(kTraits[i].product) != i) return false;
  return true;
}
static_assert(in_enum_order(), "kTraits: one row per Product, in the enum's order");

bool known(Product p) { return static_cast<std::size_t>(p) < std::size(kTraits); }

}  // namespace

std::span<const ProductTraits> all_product_traits() { return kTraits; }

const ProductTraits& traits(Product p) {
  if (!known(p)) throw std::invalid_argument("unknown product " + std::to_string(static_cast<int>(p)));
  return kTraits[static_cast<std::size_t>(p)];
}

std::string_view product_name(Product p) { return known(p) ? traits(p).name : "unknown"; }

std::string horizon_band_name(int k, int azimuths) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "horizon_az%05.1f", 360.0 * k / azimuths);
  return buf;
}

std::optional<Product> parse_product(std::string_view name) {
  for (const ProductTraits& t : kTraits)
    if (t.name == name) return t.product;
  return std::nullopt;
}

std::string product_names() {
  std::string out;
  for (const ProductTraits& t : kTraits) out += (out.empty() ? "" : ", ") + std::string(t.name);
  return out;
}

void validate_subsample(const ProductOptions& options) {
  const int s = options.subsample;
  if (s != 1 && s != 2 && s != 4) throw std::invalid_argument("subsample must be 1, 2 or 4");
  if (s != 1 && options.exact)
    throw std::invalid_argument("subsample does not apply to the exact march (the ground truth)");
}

bool uses_lighting(Product product, const ProductOptions& options) {
  const ProductTraits& t = traits(product);
  return t.needs_sun || (t.lit && options.lighting.has_value());
}

bool rgb_bands(Product product, const ProductOptions& options) {
  return traits(product).rgb_when_colour && uses_lighting(product, options) && options.lighting &&
         options.lighting->colour;
}

int band_count(Product product, const ProductOptions& options) {
  if (traits(product).band_per_azimuth) return options.march.azimuths;
  return rgb_bands(product, options) ? 3 : 1;
}

std::vector<std::string> band_names(Product product, const ProductOptions& options) {
  if (traits(product).band_per_azimuth) {
    std::vector<std::string> names;
    for (int k = 0; k < options.march.azimuths; ++k) names.push_back(horizon_band_name(k, options.march.azimuths));
    return names;
  }
  if (rgb_bands(product, options)) return {"red", "green", "blue"};
  return {std::string(traits(product).name)};
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

namespace {

// Σ_k slice(max(σ_k, 0), heading_of(k))·2π/W: the uniform sky exists only above the
// horizontal.
template <class HeadingOf>
double skyview_sum(std::span<const double> sigma, const glm::dvec3& normal, const HeadingOf& heading_of) {
  double sum = 0.0;
  for (std::size_t k = 0; k < sigma.size(); ++k) {
    const horizon::Heading u = heading_of(k);
    sum += skyview_slice_integral(std::max(sigma[k], 0.0), normal, u.east, u.north);
  }
  return sum * horizon::kTwoPi / static_cast<double>(sigma.size());
}

}  // namespace

double skyview_from_horizon(const std::vector<double>& sigma, const glm::dvec3& normal) {
  const int w = static_cast<int>(sigma.size());
  return skyview_sum(sigma, normal, [w](std::size_t k) {
    return horizon::heading_from_geographic(horizon::band_azimuth(static_cast<int>(k), w));
  });
}

double skyview_from_horizon(std::span<const double> sigma, std::span<const horizon::Heading> headings,
                            const glm::dvec3& normal) {
  return skyview_sum(sigma, normal, [&headings](std::size_t k) { return headings[k]; });
}

float srgb_code_value(double linear) {
  const double x = std::clamp(linear, 0.0, 1.0);
  const double encoded = x <= kSrgbLinearLimit ? kSrgbLinearSlope * x : kSrgbScale * std::pow(x, 1.0 / kSrgbGamma) - kSrgbOffset;
  return static_cast<float>(kFirstCode + std::round(kCodeSpan * encoded));
}

float display_code_value(double linear, ToneCurve tone) {
  if (tone == ToneCurve::Srgb) return srgb_code_value(linear);
  return static_cast<float>(kFirstCode + std::round(kCodeSpan * std::clamp(linear, 0.0, 1.0)));
}

}  // namespace skylit::shading
