#include "shading/renderer.h"

#include "shading/time_integral.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace skylit::shading {

void validate(const FrameInputs& inputs) {
  for (const blockers::Sphere& s : inputs.spheres)
    if (!std::isfinite(s.centre.x) || !std::isfinite(s.centre.y) || !std::isfinite(s.centre.z) ||
        !(s.radius > 0.0) || !std::isfinite(s.radius))
      throw std::invalid_argument("a sphere blocker needs a finite centre and a finite radius > 0");
  if (inputs.exposure && !(*inputs.exposure > 0.0 && std::isfinite(*inputs.exposure)))
    throw std::invalid_argument("a frame's exposure must be finite and > 0");
  if (inputs.lighting) validate(*inputs.lighting);
}

std::optional<int> max_square_side(Renderer& renderer, Product product, const ProductOptions& options) {
  if (renderer.fits_field(kMaxFieldSide, kMaxFieldSide, product, options)) return std::nullopt;
  int lo = 2, hi = kMaxFieldSide;  // lo fits (or is the floor), hi does not
  if (!renderer.fits_field(lo, lo, product, options)) return lo;
  while (hi - lo > 1) {
    const int mid = lo + (hi - lo) / 2;
    (renderer.fits_field(mid, mid, product, options) ? lo : hi) = mid;
  }
  return lo;
}

ProductOptions frame_options(const ProductOptions& options, const FrameInputs& inputs) {
  ProductOptions o = options;
  o.lighting = inputs.lighting;
  if (inputs.exposure) o.shaded.exposure = *inputs.exposure;
  return o;
}

std::optional<ProductBands> night_shadow(Product product, const FrameInputs& inputs, const terrain::HeightField& field) {
  if (!traits(product).sun_only || !inputs.lighting || sun_above_horizon(inputs.lighting->sun)) return std::nullopt;
  ProductBands out{field.width, field.height, 1, std::vector<float>(field.size(), 0.0f),
                   {std::string(product_name(product))}};
  for (std::size_t t = 0; t < field.size(); ++t)
    if (!field.valid[t]) out.data[t] = std::numeric_limits<float>::quiet_NaN();
  return out;
}

bool same_horizon_options(const ProductOptions& a, const ProductOptions& b) {
  return same_baked_horizon_options(a, b) && a.march.region == b.march.region;
}

bool same_baked_horizon_options(const ProductOptions& a, const ProductOptions& b) {
  const horizon::MarchOptions &m = a.march, &n = b.march;
  return m.azimuths == n.azimuths && m.k_v == n.k_v && m.levels == n.levels && m.level_offset == n.level_offset &&
         m.max_distance_m == n.max_distance_m && m.smooth_max == n.smooth_max && m.use_pyramid == n.use_pyramid &&
         m.level_interpolation == n.level_interpolation && m.curvature.enabled == n.curvature.enabled &&
         m.curvature.radius_m == n.curvature.radius_m && m.curvature.refraction_k == n.curvature.refraction_k &&
         m.method == n.method && m.sweep_near_steps == n.sweep_near_steps && m.sweep_lines == n.sweep_lines &&
         a.exact == b.exact && a.exact_options.sky_azimuths == b.exact_options.sky_azimuths &&
         a.exact_options.step_texels == b.exact_options.step_texels && a.subsample == b.subsample &&
         a.shaded.mode == b.shaded.mode && a.shaded.sh_order == b.shaded.sh_order &&
         a.shaded.nlp_order == b.shaded.nlp_order && a.shaded.wedge == b.shaded.wedge;
}

const ProductBands* FrameIndependentCache::find(Product product, const terrain::HeightField& field,
                                                const ProductOptions& options) const {
  for (const Entry& e : entries_)
    if (e.product == product && e.field_id == field.id.value() && e.revision == field.revision &&
        same_horizon_options(e.options, options))
      return &e.bands;
  return nullptr;
}

void FrameIndependentCache::store(Product product, const terrain::HeightField& field, const ProductOptions& options,
                                  const ProductBands& bands) {
  std::erase_if(entries_, [&](const Entry& e) { return e.product == product; });
  entries_.push_back({product, field.id.value(), field.revision, options, bands});
}

}  // namespace skylit::shading
