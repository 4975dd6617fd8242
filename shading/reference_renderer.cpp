#include "shading/reference_renderer.h"

#include "parallel/parallel_rows.h"

#include "shading/blocker_frame.h"
#include "shading/horizon/azimuth.h"
#include "shading/horizon/horizon_subsample.h"
#include "shading/horizon/horizon_sweep.h"
#include "shading/horizon/surface_normals.h"
#include "shading/local_products.h"
#include "shading/reference_pipeline.h"
#include "shading/sh/wedge.h"
#include "shading/shading_modes.h"
#include "shading/sun_light.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <stdexcept>

namespace skylit::shading {

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
// Share of the progress bar for the sun's pass in lit products (1 ray vs W).
constexpr double kSunShare = 0.1;

// Headings of the W product bands (geographic) or of the wedge samples (math frame).
std::vector<horizon::Heading> geographic_headings(int w) {
  std::vector<horizon::Heading> h(w);
  for (int k = 0; k < w; ++k) h[k] = horizon::heading_from_geographic(horizon::band_azimuth(k, w));
  return h;
}
std::vector<horizon::Heading> math_headings(int w) {
  std::vector<horizon::Heading> h(w);
  for (int k = 0; k < w; ++k) h[k] = horizon::heading_from_math(horizon::kTwoPi * k / w);
  return h;
}

// Lambert shading of the sky light for one channel: ∫ L·V·max(n·ω, 0)/π dω, in the
// chosen mode; LogBrdf works from the log-visibility, the others from V.
class SkyShading {
 public:
  SkyShading(ShadingMode mode, int order, const SkyInput& sky)
      : shader_(std::make_unique<Shader>(sky_shading_settings(mode, order), sky)) {}
  bool needs_log() const { return shader_->settings().mode == ShadingMode::LogBrdf; }
  double radiance(std::span<const double> vis, std::span<const double> log_vis, const glm::dvec3& n) const {
    return needs_log() ? shader_->shade_log(log_vis, n, n) : shader_->shade(vis, n, n);
  }

 private:
  std::unique_ptr<Shader> shader_;
};

// Sky shading and sun of a Lighting for `shaded` and `irradiance`: one sky shading per
// output channel — R, G, B for a colour `shaded`, else the broadband luminance.
class LitShading {
 public:
  LitShading(const Lighting& l, bool rgb, ShadingMode mode, int order) : sun_(l.sun.direction) {
    for (int c = 0; c < (rgb ? 3 : 1); ++c) dni_.push_back(rgb ? l.sun.dni[c] : sky::luminance(l.sun.dni));
    for (const SkyInput& in : channel_sky_inputs(l, rgb, mode, order))
      sky_.push_back(std::make_unique<SkyShading>(mode, order, in));
  }
  int channels() const { return static_cast<int>(dni_.size()); }
  // Irradiance of channel c (W/m²): π·(sky shading) (= ∫ L·V·max(n·ω, 0) dω) plus the sun.
  double irradiance(int c, std::span<const double> vis, std::span<const double> log_vis, const glm::dvec3& n,
                    double shadow) const {
    const double sky = sky_.empty() ? 0.0 : std::numbers::pi * sky_[c]->radiance(vis, log_vis, n);
    return std::max(sky + sun_irradiance(n, sun_, dni_[c], shadow), 0.0);
  }

 private:
  glm::dvec3 sun_;
  std::vector<double> dni_;
  std::vector<std::unique_ptr<SkyShading>> sky_;
};

// The raw horizons σ_k (no floor) of every texel, ProductOptions::subsample (products.h):
// s = 1 marches (or sweeps) each texel. s > 1 first finds those of the coarse texels of
// the whole field (march_coarse, after sweep()); a texel's σ_k is then the bilinear mix
// of its bracketing coarse samples. Where one of them is not finite (nodata coarse
// texel: NaN, never found; no step on the grid: −∞) the march takes the texel's own
// march, the sweep the mix of the finite ones, weights renormalised (−∞ if none): the
// sweep has far slopes for the coarse texels alone. Holds (W_f/s)·(H_f/s)·W doubles.
class HorizonSource {
 public:
  HorizonSource(const HorizonOracle& oracle, const terrain::HeightField& field, const ProductOptions& options,
                const std::vector<horizon::Heading>& headings)
      : oracle_(oracle), field_(field), headings_(headings), cols_{field.width, options.subsample},
        rows_{field.height, options.subsample}, march_(options.march), sweep_(uses_sweep(field, options)) {}

  // Sweep: the far slopes of every heading (W·N² codes), before horizons(); sub-sampled,
  // those of the texels whose own horizons are taken, over the region's coarse texels.
  void sweep(unsigned threads, const ProgressCallback& progress) {
    if (!sweep_) return;
    far_.resize(headings_.size());
    horizon::MarchOptions m = march_;
    m.region = horizon::subsample_region(field_, m.region, cols_.step);
    parallel::parallel_rows(static_cast<int>(headings_.size()), threads, [&](int k) {
      far_[k] = horizon::sweep_far_slopes(field_, headings_[k], m, 1, -std::numeric_limits<double>::infinity(),
                                          cols_.step);
    }, progress);
  }

  bool subsampled() const { return cols_.step > 1; }
  bool sweeps() const { return sweep_; }
  // Share of the texels' work done by march_coarse (for progress): coarse / (coarse + all).
  double coarse_share() const {
    if (!subsampled()) return 0.0;
    const double coarse = static_cast<double>(cols_.count()) * rows_.count();
    return coarse / (coarse + static_cast<double>(field_.size()));
  }

  void march_coarse(unsigned threads, const ProgressCallback& progress) {
    if (!subsampled()) return;
    if (sweep_ && far_.empty()) throw std::logic_error("HorizonSource: march_coarse before sweep");
    const std::size_t w = headings_.size();
    coarse_.assign(static_cast<std::size_t>(cols_.count()) * rows_.count() * w,
                   std::numeric_limits<double>::quiet_NaN());
    parallel::parallel_rows(rows_.count(), threads, [&](int cj) {
      const int j = rows_.position(cj);
      for (int ci = 0; ci < cols_.count(); ++ci) {
        const int i = cols_.position(ci);
        if (!field_.is_valid(i, j)) continue;  // stays NaN
        for (std::size_t k = 0; k < w; ++k) coarse_[index(ci, cj, k)] = own(i, j, k);
      }
    }, progress);
  }

  void horizons(int i, int j, std::vector<double>& sigma) const {
    if (!subsampled()) {
      for (std::size_t k = 0; k < headings_.size(); ++k) sigma[k] = own(i, j, k);
      return;
    }
    const horizon::SubsampleAxis::Bracket x = cols_.bracket(i), y = rows_.bracket(j);
    if (sweep_) {
      for (std::size_t k = 0; k < headings_.size(); ++k) sigma[k] = finite_mix(x, y, k);
      return;
    }
    for (std::size_t k = 0; k < headings_.size(); ++k) {
      auto along_row = [&](int cj) {
        const double v0 = coarse_[index(x.c0, cj, k)];
        return x.c1 == x.c0 ? v0 : (1.0 - x.a) * v0 + x.a * coarse_[index(x.c1, cj, k)];
      };
      const double r0 = along_row(y.c0);
      // Non-finite iff a sample with a non-zero weight is (σ is never +∞).
      const double v = y.c1 == y.c0 ? r0 : (1.0 - y.a) * r0 + y.a * along_row(y.c1);
      sigma[k] = std::isfinite(v) ? v : own(i, j, k);
    }
  }

 private:
  // The bilinear mix of the finite samples of band k at the bracket (x, y), their weights
  // renormalised; −∞ if none is finite.
  double finite_mix(const horizon::SubsampleAxis::Bracket& x, const horizon::SubsampleAxis::Bracket& y,
                    std::size_t k) const {
    double sum = 0.0, weight = 0.0;
    for (const auto& [cj, wy] : {std::pair{y.c0, 1.0 - y.a}, std::pair{y.c1, y.a}})
      for (const auto& [ci, wx] : {std::pair{x.c0, 1.0 - x.a}, std::pair{x.c1, x.a}}) {
        const double v = coarse_[index(ci, cj, k)];
        if (!std::isfinite(v)) continue;
        sum += wx * wy * v;
        weight += wx * wy;
      }
    return weight > 0.0 ? sum / weight : -std::numeric_limits<double>::infinity();
  }
  // Texel (i, j)'s own raw horizon in band k: swept or marched.
  double own(int i, int j, std::size_t k) const {
    if (!sweep_) return oracle_.max_elevation(i, j, headings_[k]);
    return horizon::sweep_max_elevation(field_, i, j, headings_[k],
                                        far_[k][static_cast<std::size_t>(j) * field_.width + i], march_);
  }

  std::size_t index(int ci, int cj, std::size_t k) const {
    return (static_cast<std::size_t>(cj) * cols_.count() + ci) * headings_.size() + k;
  }

  const HorizonOracle& oracle_;
  const terrain::HeightField& field_;
  const std::vector<horizon::Heading>& headings_;
  horizon::SubsampleAxis cols_, rows_;
  std::vector<double> coarse_;  // [(cj·count_x + ci)·W + k]
  const horizon::MarchOptions& march_;
  bool sweep_;
  std::vector<std::vector<std::uint16_t>> far_;  // sweep: codes per heading, [j·width + i]
};

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

void ReferenceRenderer::set_options(const ProductOptions& options) {
  if (!same_horizon_options(options, options_)) drop_horizons();
  options_ = options;
}

void ReferenceRenderer::drop_horizons() {
  visibility_ = {};
  outputs_.clear();
  frames_ = 0;
}

ProductBands ReferenceRenderer::frame(Product product, const FrameInputs& inputs, const ProgressCallback& progress) {
  if (!field_) throw std::logic_error("ReferenceRenderer::frame: no field (set_field)");
  validate(inputs);
  const auto start = std::chrono::steady_clock::now();
  timings_ = {};
  const ProductOptions options = frame_options(options_, inputs);
  ProductBands out;
  if (traits(product).local) {
    out = compute_local_product(*field_, product, options);
  } else if (auto night = night_shadow(product, inputs, *field_)) {
    out = std::move(*night);
  } else if (FrameIndependentCache::applies(product) && !blocked_frame(product, inputs)) {
    out = outputs_.get(product, *field_, options, keep_ || frames_ > 0, progress, timings_.horizons_reused,
                       [&] { return render(product, options, {}, progress); });
  } else {
    std::span<const blockers::Sphere> spheres;
    if (blocked_frame(product, inputs)) spheres = inputs.spheres;
    out = render(product, options, spheres, progress);
  }
  ++frames_;
  timings_.frame_ms = ms_since(start);
  return out;
}

ProductBands ReferenceRenderer::render(Product product, const ProductOptions& options,
                                       std::span<const blockers::Sphere> spheres, const ProgressCallback& progress) {
  const terrain::HeightField& field = *field_;
  if (field.width < 1 || field.height < 1) throw std::invalid_argument("compute_product: empty height field");
  validate_subsample(options);
  const HorizonOracle oracle(field, options);
  const int w_march = options.march.azimuths;
  const int w_sky = options.exact ? options.exact_options.sky_azimuths : w_march;
  if (w_sky < 1) throw std::invalid_argument("exact: sky azimuths must be ≥ 1");
  if (!(options.shaded.albedo >= 0.0) || !(options.shaded.exposure > 0.0))
    throw std::invalid_argument("shaded: albedo must be ≥ 0 and exposure > 0");
  const bool lit = uses_lighting(product, options);
  if (lit && !options.lighting)
    throw std::invalid_argument(std::string(product_name(product)) + " needs a sun: ProductOptions::lighting");
  const ProductTraits& kind = traits(product);
  const bool rgb = rgb_bands(product, options);
  std::optional<BlockerFrame> blockers;
  if (!spheres.empty()) blockers.emplace(field, spheres, options);
  const bool log_route = options.shaded.mode == ShadingMode::LogBrdf;
  if (blockers && options.exact && log_route)
    throw std::invalid_argument("the exact truth with sphere blockers needs the table or triple-product shading mode");

  ProductBands out;
  out.width = field.width;
  out.height = field.height;
  out.bands = band_count(product, options);
  out.data.assign(static_cast<std::size_t>(out.bands) * field.size(), kNaN);
  out.band_names = band_names(product, options);
  auto put = [&](int b, int i, int j, double v) {
    out.data[(static_cast<std::size_t>(b) * field.height + j) * field.width + i] = static_cast<float>(v);
  };

  // Sun: the visible disc fraction of every texel, in its own pass (its own march).
  std::vector<float> shadow;
  const bool sun_lit = lit && sky::luminance(options.lighting->sun.dni) > 0.0;
  if (kind.sun_only || sun_lit) {
    const glm::dvec3& s = options.lighting->sun.direction;
    const bool alone = kind.sun_only;
    shadow = shadow_fraction_field(field, {sky::azimuth_of(s), sky::elevation_of(s)}, sun_shadow_options(options),
                                   [&](double f) {
                                     if (progress) progress(alone ? f : kSunShare * f);
                                   });
    if (blockers)
      parallel::parallel_rows(field.height, options.threads, [&](int j) {
        for (int i = 0; i < field.width; ++i) {
          float& f = shadow[static_cast<std::size_t>(j) * field.width + i];
          if (f > 0.0f) f = static_cast<float>(f * blockers->sun_left(i, j, s));
        }
      });
    if (alone) {
      std::copy(shadow.begin(), shadow.end(), out.data.begin());
      return out;
    }
  }
  const auto main_progress = [&](double f) {
    if (progress) progress(shadow.empty() ? f : kSunShare + (1.0 - kSunShare) * f);
  };

  // Shading set-up: wedge operator, and either the default shading mode (sky × BRDF
  // table, Lambert) under a uniform sky of radiance 1 above the horizontal, or the
  // lighting's sky tables and sun.
  // With blockers, skyview too needs the SH visibility: its change is shaded by the
  // uniform sky's table.
  const bool needs_visibility = kind.needs_visibility;
  const bool sh_visibility = needs_visibility || blockers.has_value();
  const sh::WedgeOperator* wedge = nullptr;
  std::unique_ptr<SkyShading> uniform_sky;
  std::unique_ptr<LitShading> lighting;
  if (product == Product::Skyview && blockers) {
    const ShadedOptions& s = options.shaded;
    wedge = &sh::wedge_operator(s.sh_order, s.nlp_order, w_sky, s.wedge);
    uniform_sky = std::make_unique<SkyShading>(ShadingMode::SkyBrdfTable, s.sh_order,
                                               sky_input(ShadingMode::SkyBrdfTable, s.sh_order, uniform_sky_radiance(), true));
  } else if (needs_visibility) {
    const ShadedOptions& s = options.shaded;
    wedge = &sh::wedge_operator(s.sh_order, s.nlp_order, w_sky, s.wedge);
    if (lit)
      lighting = std::make_unique<LitShading>(*options.lighting, rgb, s.mode, s.sh_order);
    else
      uniform_sky = std::make_unique<SkyShading>(s.mode, s.sh_order,
                                                 sky_input(s.mode, s.sh_order, uniform_sky_radiance(), true));
  }
  // Tone map of the lit `shaded` (lighting.h): E → linear display value.
  const double display_per_irradiance =
      lit ? shaded_display_scale(options.shaded, *options.lighting) : 0.0;

  // The visibility of an earlier frame on this field revision and these horizon options,
  // or (keeping) this frame's, for the frames after it.
  const bool reuse = needs_visibility && !blockers && visibility_.field_id == field.id.value() &&
                     visibility_.revision == field.revision && same_horizon_options(visibility_.options, options);
  const bool keep = needs_visibility && !reuse && (keep_ || frames_ > 0);
  if (keep) {
    visibility_ = {field.id.value(), field.revision, options, static_cast<int>(wedge->rows()), {}};
    visibility_.values.assign(field.size() * wedge->rows(), 0.0);
  }
  timings_.horizons_reused = reuse;

  const std::vector<horizon::Heading> headings =
      kind.band_per_azimuth ? geographic_headings(w_march)
      : sh_visibility       ? math_headings(w_sky)
                            : geographic_headings(w_sky);

  // Raw horizons: with sub-sampling, the coarse texels are marched first.
  HorizonSource horizons(oracle, field, options, headings);
  double coarse_share = 0.0, sweep_share = 0.0;
  if (!reuse) {
    sweep_share = horizons.sweeps() ? 0.5 : 0.0;
    coarse_share = (1.0 - sweep_share) * horizons.coarse_share();
    horizons.sweep(options.threads, [&](double f) { main_progress(sweep_share * f); });
    horizons.march_coarse(options.threads, [&](double f) { main_progress(sweep_share + coarse_share * f); });
  }

  parallel::parallel_rows(field.height, options.threads, [&](int j) {
    std::vector<double> sigma(headings.size());
    std::vector<double> scratch, vis, log_vis, delta, log_sum, block_scratch;
    if (wedge) {
      scratch.resize(static_cast<std::size_t>(wedge->azimuths()) * wedge->nlp_order());
      vis.resize(wedge->rows());
      if (log_route || blockers) log_vis.resize(wedge->rows());
      if (blockers) {
        delta.resize(wedge->rows());
        log_sum.resize(wedge->rows());
        block_scratch.resize(3 * wedge->rows());
      }
    }
    // Visibility horizons: floored at the tangent plane (math-notes §10.14).
    auto floor_horizons = [&](const glm::dvec3& n) {
      for (std::size_t k = 0; k < sigma.size(); ++k)
        sigma[k] = std::clamp(std::max(sigma[k], horizon::tangent_plane_floor(n, headings[k])), -std::numbers::pi / 2,
                              std::numbers::pi / 2);
    };
    // ΔV of the spheres at texel (i, j) from the floored horizons, into `delta` (and the
    // log sum into log_sum); false where none touches it. Needs the terrain's vis; makes
    // its log_vis where the composition or the log route needs it and it is not made.
    const bool needs_log_t = log_route || options.blockers.composition != blockers::Composition::kProduct;
    auto block = [&](int i, int j, const glm::dvec3& n) {
      if (!blockers || !blockers->touches_sky(i, j)) return false;
      if (options.exact) {
        blockers->exact_sky_delta(i, j, sigma, delta);
        return true;
      }
      if (needs_log_t && !log_route)
        sh::log_visibility_from_horizon(*wedge, sigma, std::log(sh::kDefaultLogEpsilon), scratch, log_vis);
      const std::span<const double> log_t = needs_log_t ? std::span<const double>(log_vis) : std::span<const double>();
      return blockers->sky_delta(i, j, n, sigma, vis, log_t, delta, log_sum, block_scratch) > 0;
    };
    for (int i = 0; i < field.width; ++i) {
      if (!field.is_valid(i, j)) continue;  // stays NaN
      const glm::dvec3 n = horizon::horn_normal(field, i, j);
      if (!reuse) horizons.horizons(i, j, sigma);
      switch (product) {
        case Product::Horizon:
          for (int k = 0; k < w_march; ++k)
            put(k, i, j, std::max(sigma[k], oracle.ground_floor(j, headings[k])) * 180.0 / std::numbers::pi);
          break;
        case Product::Svf: put(0, i, j, svf_from_horizon(sigma)); break;
        case Product::Skyview: {
          if (!blockers) {
            put(0, i, j, skyview_from_horizon(sigma, n));
            break;
          }
          double skyview = skyview_from_horizon(sigma, headings, n);  // the math azimuths
          if (blockers->touches_sky(i, j)) {
            if (options.exact) {
              skyview += blockers->exact_skyview_delta(i, j, n, sigma);
            } else {
              floor_horizons(n);
              sh::visibility_from_horizon(*wedge, sigma, scratch, vis);
              if (block(i, j, n)) skyview += uniform_sky->radiance(delta, {}, n);
            }
          }
          put(0, i, j, skyview);
          break;
        }
        case Product::Shaded:
        case Product::Irradiance: {
          std::vector<double>& v = log_route ? log_vis : vis;
          const std::size_t texel = static_cast<std::size_t>(j) * field.width + i;
          if (reuse) {
            std::copy_n(visibility_.values.begin() + static_cast<std::ptrdiff_t>(texel * v.size()), v.size(), v.begin());
          } else {
            floor_horizons(n);
            if (log_route)
              sh::log_visibility_from_horizon(*wedge, sigma, std::log(sh::kDefaultLogEpsilon), scratch, log_vis);
            if (!log_route || blockers) sh::visibility_from_horizon(*wedge, sigma, scratch, vis);
            if (keep)
              std::copy(v.begin(), v.end(), visibility_.values.begin() + static_cast<std::ptrdiff_t>(texel * v.size()));
            if (block(i, j, n)) {
              if (log_route)
                std::copy(log_sum.begin(), log_sum.end(), log_vis.begin());
              else
                for (std::size_t q = 0; q < vis.size(); ++q) vis[q] += delta[q];
            }
          }
          if (!lighting) {
            const double radiance = options.shaded.albedo * uniform_sky->radiance(vis, log_vis, n);
            put(0, i, j, display_code_value(radiance * options.shaded.exposure, options.shaded.tone));
            break;
          }
          const double sun = shadow.empty() ? 0.0 : shadow[texel];
          for (int c = 0; c < lighting->channels(); ++c) {
            const double e = lighting->irradiance(c, vis, log_vis, n, sun);
            put(c, i, j, kind.eight_bit ? display_code_value(e * display_per_irradiance, options.shaded.tone) : e);
          }
          break;
        }
        case Product::Shadow: break;     // returned above
        case Product::Hillshade: break;  // local: compute_local_product, before the horizons
      }
    }
  }, [&](double f) { main_progress(coarse_share + sweep_share + (1.0 - coarse_share - sweep_share) * f); });
  return out;
}

ProductBands compute_product(const terrain::HeightField& field, Product product, const ProductOptions& options,
                             const ProgressCallback& progress) {
  ReferenceRenderer renderer;
  renderer.set_field(field);
  renderer.set_options(options);
  return renderer.frame(product, FrameInputs{options.lighting, {}, std::nullopt}, progress);
}

}  // namespace skylit::shading
