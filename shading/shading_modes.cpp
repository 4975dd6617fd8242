#include "shading/shading_modes.h"

#include "shading/sh/sh_rotation.h"

#include <stdexcept>
#include <vector>

namespace skylit::shading {
namespace {

constexpr int kMaxCoeffs = sh::kMaxOrder * sh::kMaxOrder;

int checked_order(std::size_t size) {
  const int order = sh::order_of(size);
  if (order > sh::kMaxOrder) throw std::invalid_argument("shading: order above sh::kMaxOrder");
  return order;
}

}  // namespace

std::string_view to_string(ShadingMode mode) {
  switch (mode) {
    case ShadingMode::LogBrdf:
      return "log-brdf";
    case ShadingMode::TripleProduct:
      return "triple";
    case ShadingMode::SkyBrdfTable:
      return "table";
  }
  return "?";
}

std::optional<ShadingMode> parse_shading_mode(std::string_view name) {
  for (ShadingMode m : {ShadingMode::LogBrdf, ShadingMode::TripleProduct, ShadingMode::SkyBrdfTable})
    if (name == to_string(m)) return m;
  return std::nullopt;
}

sh::HybOptions log_brdf_hyb_options() {
  sh::HybOptions opt;
  opt.clamp_output_dc = false;
  opt.log_floor_epsilon = 0.0;
  return opt;
}

double shade_triple_product(const sh::TripleProduct& gamma, std::span<const double> visibility,
                            std::span<const double> sky_sh, std::span<const double> lobe_zh, const glm::dvec3& axis) {
  const int order = checked_order(visibility.size());
  if (sky_sh.size() != visibility.size() || gamma.order() != order)
    throw std::invalid_argument("shade_triple_product: size mismatch");
  const std::size_t nc = visibility.size();
  double f[kMaxCoeffs] = {}, vf[kMaxCoeffs];
  sh::add_rotated_zh(lobe_zh, axis, 1.0, std::span<double>(f, nc));
  gamma.product(visibility, std::span<const double>(f, nc), std::span<double>(vf, nc));
  return sh::dot(std::span<const double>(vf, nc), sky_sh);
}

double shade_log_brdf(std::span<const double> log_visibility, std::span<const double> sky_sh,
                      std::span<const double> log_lobe_zh, const glm::dvec3& axis, LogExp method,
                      const sh::HybOptions& hyb) {
  checked_order(log_visibility.size());
  if (sky_sh.size() != log_visibility.size()) throw std::invalid_argument("shade_log_brdf: size mismatch");
  const std::size_t nc = log_visibility.size();
  double sum[kMaxCoeffs], e[kMaxCoeffs];
  std::copy(log_visibility.begin(), log_visibility.end(), sum);
  const std::span<double> s(sum, nc);
  sh::add_rotated_zh(log_lobe_zh, axis, 1.0, s);
  switch (method) {
    case LogExp::Hyb:
      sh::exp_hyb<double>(s, std::span<double>(e, nc), hyb);
      return sh::dot(std::span<const double>(e, nc), sky_sh);
    case LogExp::Pointwise:
      return sh::dot(sh::exp_pointwise(s), sky_sh);
    case LogExp::ProductAlgebra:
      return sh::dot(sh::exp_product_algebra(s), sky_sh);
  }
  throw std::invalid_argument("shade_log_brdf: unknown method");
}

AxisGrid table_grid_for(const ShadingSettings& s) {
  if (s.table_grid) return *s.table_grid;
  return s.brdf.kind == BrdfKind::Lambert ? AxisGrid::hemisphere() : AxisGrid::sphere();
}

Shader::Shader(const ShadingSettings& settings, const SkyInput& sky) : settings_(settings) {
  if (settings.order < sh::kMinOrder || settings.order > sh::kMaxOrder)
    throw std::invalid_argument("Shader: order out of range");
  lobe_zh_ = brdf_zh(settings.order, settings.brdf);
  if (settings.mode == ShadingMode::LogBrdf)
    log_lobe_zh_ = log_brdf_zh(settings.order, settings.brdf, settings.log_epsilon);
  if (settings.mode == ShadingMode::TripleProduct) gamma_ = &sh::triple_product(settings.order);
  set_sky(sky);
}

void Shader::set_sky(const SkyInput& sky) {
  if (settings_.mode == ShadingMode::SkyBrdfTable) {
    if (sky.table) {
      if (sky.table->order() != settings_.order || sky.table->lobe_exponent() != settings_.brdf.lobe_exponent())
        throw std::invalid_argument("Shader: the sky's table was built for other settings");
      table_ = sky.table;
      return;
    }
    if (!sky.radiance) throw std::invalid_argument("Shader: table mode needs the sky radiance function");
    table_ = std::make_shared<SkyBrdfTable>(settings_.order, settings_.brdf.lobe_exponent(), sky.radiance,
                                            table_grid_for(settings_), settings_.table_quadrature, sky.z_symmetric);
    return;
  }
  if (sky.sh.size() != static_cast<std::size_t>(sh::num_coeffs(settings_.order)))
    throw std::invalid_argument("Shader: sky SH vector of the wrong order");
  sky_sh_ = sky.sh;
}

double Shader::shade(std::span<const double> visibility, const glm::dvec3& normal, const glm::dvec3& to_viewer) const {
  const glm::dvec3 axis = lobe_axis(settings_.brdf, normal, to_viewer);
  switch (settings_.mode) {
    case ShadingMode::SkyBrdfTable:
      return table_->shade(visibility, axis);
    case ShadingMode::TripleProduct:
      return shade_triple_product(*gamma_, visibility, sky_sh_, lobe_zh_, axis);
    case ShadingMode::LogBrdf:
      break;
  }
  throw std::logic_error("Shader::shade: the log-BRDF mode needs a log-visibility (shade_log)");
}

double Shader::shade_log(std::span<const double> log_visibility, const glm::dvec3& normal,
                         const glm::dvec3& to_viewer) const {
  if (settings_.mode == ShadingMode::LogBrdf)
    return shade_log_brdf(log_visibility, sky_sh_, log_lobe_zh_, lobe_axis(settings_.brdf, normal, to_viewer),
                          settings_.log_exp, settings_.log_hyb);
  const std::size_t nc = log_visibility.size();
  checked_order(nc);
  double v[kMaxCoeffs];
  sh::exp_hyb<double>(log_visibility, std::span<double>(v, nc), settings_.visibility_hyb);
  return shade(std::span<const double>(v, nc), normal, to_viewer);
}

}  // namespace skylit::shading
