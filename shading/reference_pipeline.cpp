#include "shading/reference_pipeline.h"

#include "shading/horizon/azimuth.h"
#include "shading/horizon/horizon_subsample.h"
#include "shading/horizon/horizon_sweep.h"
#include "shading/horizon/surface_normals.h"
#include "shading/sh/quadrature.h"
#include "shading/sh/sh_exp.h"
#include "shading/sh/wedge.h"
#include "shading/shading_modes.h"
#include "shading/sun_light.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace skylit::shading {

bool uses_sweep(const terrain::HeightField& field, const ProductOptions& options) {
  return options.march.method == horizon::HorizonMethod::Sweep && !options.exact &&
         horizon::sweep_applicable(field, options.march);
}

HorizonOracle::HorizonOracle(const terrain::HeightField& field, const ProductOptions& options) : field_(field) {
  validate(options.march);
  if (uses_sweep(field, options)) {  // no pyramid: HorizonSource sweeps; the floor is the half texel's
    exact_ = horizon::ExactMarch{0.5, options.march.max_distance_m, options.march.curvature};
    return;
  }
  if (!options.exact) {
    marcher_ = std::make_unique<horizon::HorizonMarcher>(field, options.march);
    return;
  }
  if (!(options.exact_options.step_texels > 0.0)) throw std::invalid_argument("exact: step must be > 0");
  exact_ = horizon::ExactMarch{options.exact_options.step_texels, options.march.max_distance_m,
                               options.march.curvature};
}

double HorizonOracle::max_elevation(int i, int j, horizon::Heading u) const {
  return marcher_ ? marcher_->max_elevation(i, j, u) : horizon::exact_max_elevation(field_, i, j, u, exact_);
}

double HorizonOracle::ground_floor(int j, horizon::Heading u) const {
  const horizon::EarthCurvature& c = marcher_ ? marcher_->options().curvature : exact_.curvature;
  if (!c.enabled) return 0.0;
  const double t1 = marcher_ ? marcher_->distance(0) : horizon::exact_step_length(field_, j, u, exact_.step_texels);
  return -std::atan(t1 / (2.0 * c.effective_radius()));
}

ShadingSettings sky_shading_settings(ShadingMode mode, int order) {
  ShadingSettings settings;
  settings.mode = mode;
  settings.order = order;
  return settings;
}

std::vector<SkyInput> channel_sky_inputs(const Lighting& l, bool rgb, ShadingMode mode, int order) {
  std::vector<SkyInput> inputs;
  if (!l.sky) return inputs;
  const bool z_symmetric = l.sky->azimuthally_symmetric();
  for (int c = 0; c < (rgb ? 3 : 1); ++c) inputs.push_back(sky_input(mode, order, channel_radiance(l.sky, rgb, c), z_symmetric));
  if (rgb && mode == ShadingMode::SkyBrdfTable) {
    const ShadingSettings s = sky_shading_settings(mode, order);
    const auto tables = SkyBrdfTable::rgb(order, s.brdf.lobe_exponent(),
                                          [sky = l.sky](const glm::dvec3& d) { return sky->radiance(d); },
                                          table_grid_for(s), s.table_quadrature, z_symmetric);
    for (int c = 0; c < 3; ++c) inputs[c].table = tables[c];
  }
  return inputs;
}

SkyInput sky_input(ShadingMode mode, int order, Radiance radiance, bool z_symmetric) {
  SkyInput in;
  in.z_symmetric = z_symmetric;
  if (mode != ShadingMode::SkyBrdfTable)
    in.sh = sh::project(order, sh::sphere_product_rule(64, 128, 0.0, 1.0), radiance);
  in.radiance = std::move(radiance);
  return in;
}

SunShadowOptions sun_shadow_options(const ProductOptions& o) {
  SunShadowOptions s;
  s.threads = o.threads;
  s.march.curvature = o.march.curvature;
  s.march.max_distance_m = o.march.max_distance_m;
  s.march.region = o.march.region;
  if (o.exact) {
    s.horizon = SunHorizon::Exact;
    s.exact = horizon::ExactMarch{o.exact_options.step_texels, o.march.max_distance_m, o.march.curvature};
  } else if (o.march.method == horizon::HorizonMethod::Sweep) {  // the sun's own sweep knobs; Marched where it cannot
    s.horizon = SunHorizon::Swept;
    s.march.method = horizon::HorizonMethod::Sweep;
  }
  return s;
}

Radiance channel_radiance(std::shared_ptr<const sky::SkyModel> sky, bool rgb, int channel) {
  if (rgb) return [sky, channel](const glm::dvec3& d) { return sky->radiance(d)[channel]; };
  return [sky](const glm::dvec3& d) { return sky::luminance(sky->radiance(d)); };
}

double shaded_display_scale(const ShadedOptions& shaded, const Lighting& lighting) {
  return shaded.exposure * shaded_key(shaded.tone) * shaded.albedo / lighting.reference_irradiance;
}

Radiance uniform_sky_radiance() {
  return [](const glm::dvec3& d) { return d.z > 0.0 ? 1.0 : 0.0; };
}

}  // namespace skylit::shading
