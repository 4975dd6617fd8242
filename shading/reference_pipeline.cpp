#include "shading/reference_pipeline.h"

#include "shading/azimuth.h"
#include "shading/horizon_subsample.h"
#include "shading/horizon_sweep.h"
#include "shading/shading_modes.h"
#include "shading/sh_exp.h"
#include "shading/quadrature.h"
#include "shading/sun_light.h"
#include "shading/surface_normals.h"
#include "shading/wedge.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <thread>

namespace skylit::shading {

void parallel_rows(int rows, unsigned threads, const std::function<void(int)>& body,
                   const ProgressCallback& progress) {
  if (rows <= 0) return;
  unsigned n = threads ? threads : std::max(1u, std::thread::hardware_concurrency());
  n = std::min<unsigned>(n, static_cast<unsigned>(rows));
  std::atomic<int> next{0};
  int done = 0;
  std::mutex mutex;  // guards done, error and the progress callback
  std::exception_ptr error;
  auto worker = [&] {
    for (int row; (row = next.fetch_add(1)) < rows;) {
      try {
        body(row);
        std::lock_guard lock(mutex);
        ++done;
        if (progress && !error) progress(static_cast<double>(done) / rows);
      } catch (...) {
        std::lock_guard lock(mutex);
        if (!error) error = std::current_exception();
        next = rows;
        return;
      }
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < n; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

bool uses_sweep(const terrain::HeightField& field, const ProductOptions& options) {
  return options.march.method == HorizonMethod::Sweep && !options.exact && options.subsample == 1 &&
         sweep_applicable(field, options.march);
}

HorizonOracle::HorizonOracle(const terrain::HeightField& field, const ProductOptions& options) : field_(field) {
  validate(options.march);
  if (uses_sweep(field, options)) {  // no pyramid: HorizonSource sweeps; the floor is the half texel's
    exact_ = ExactMarch{0.5, options.march.max_distance_m, options.march.curvature};
    return;
  }
  if (!options.exact) {
    marcher_ = std::make_unique<HorizonMarcher>(field, options.march);
    return;
  }
  if (!(options.exact_options.step_texels > 0.0)) throw std::invalid_argument("exact: step must be > 0");
  exact_ = ExactMarch{options.exact_options.step_texels, options.march.max_distance_m, options.march.curvature};
}

double HorizonOracle::max_elevation(int i, int j, Heading u) const {
  return marcher_ ? marcher_->max_elevation(i, j, u) : exact_max_elevation(field_, i, j, u, exact_);
}

double HorizonOracle::ground_floor(int j, Heading u) const {
  const EarthCurvature& c = marcher_ ? marcher_->options().curvature : exact_.curvature;
  if (!c.enabled) return 0.0;
  const double t1 = marcher_ ? marcher_->distance(0) : exact_step_length(field_, j, u, exact_.step_texels);
  return -std::atan(t1 / (2.0 * c.effective_radius()));
}

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
// Share of the progress bar for the sun's pass in lit products (1 ray vs W).
constexpr double kSunShare = 0.1;

// Headings of the W product bands (geographic) or of the wedge samples (math frame).
std::vector<Heading> geographic_headings(int w) {
  std::vector<Heading> h(w);
  for (int k = 0; k < w; ++k) h[k] = heading_from_geographic(band_azimuth(k, w));
  return h;
}
std::vector<Heading> math_headings(int w) {
  std::vector<Heading> h(w);
  for (int k = 0; k < w; ++k) h[k] = heading_from_math(kTwoPi * k / w);
  return h;
}

}  // namespace

SkyInput sky_input(ShadingMode mode, int order, Radiance radiance, bool z_symmetric) {
  SkyInput in;
  in.z_symmetric = z_symmetric;
  if (mode != ShadingMode::SkyBrdfTable)
    in.sh = quad::project(order, quad::sphere_product_rule(64, 128, 0.0, 1.0), radiance);
  in.radiance = std::move(radiance);
  return in;
}

namespace {

// Lambert shading of the sky light for one channel: ∫ L·V·max(n·ω, 0)/π dω, in the
// chosen mode; LogBrdf works from the log-visibility, the others from V.
class SkyShading {
 public:
  SkyShading(ShadingMode mode, int order, Radiance radiance, bool z_symmetric) {
    ShadingSettings settings;
    settings.mode = mode;
    settings.order = order;
    shader_ = std::make_unique<Shader>(settings, sky_input(mode, order, std::move(radiance), z_symmetric));
  }
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
    const int channels = rgb ? 3 : 1;
    for (int c = 0; c < channels; ++c) {
      dni_.push_back(rgb ? l.sun.dni[c] : sky::luminance(l.sun.dni));
      if (!l.sky) continue;
      sky_.push_back(std::make_unique<SkyShading>(mode, order, channel_radiance(l.sky, rgb, c),
                                                  l.sky->azimuthally_symmetric()));
    }
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
// s = 1 marches each texel. s > 1 first marches the coarse texels of the whole field
// (march_coarse); a texel's σ_k is then the bilinear mix of the coarse samples with a
// non-zero weight, or its own march where one of them is not finite (nodata coarse
// texel: NaN, never marched; no step on the grid: −∞). Holds (W_f/s)·(H_f/s)·W doubles.
class HorizonSource {
 public:
  HorizonSource(const HorizonOracle& oracle, const terrain::HeightField& field, const ProductOptions& options,
                const std::vector<Heading>& headings)
      : oracle_(oracle), field_(field), headings_(headings), cols_{field.width, options.subsample},
        rows_{field.height, options.subsample}, march_(options.march), sweep_(uses_sweep(field, options)) {}

  // Sweep: the far slopes of every heading (W·N² floats), before horizons().
  void sweep(unsigned threads, const ProgressCallback& progress) {
    if (!sweep_) return;
    far_.resize(headings_.size());
    parallel_rows(static_cast<int>(headings_.size()), threads,
                  [&](int k) { far_[k] = sweep_far_slopes(field_, headings_[k], march_); }, progress);
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
    const std::size_t w = headings_.size();
    coarse_.assign(static_cast<std::size_t>(cols_.count()) * rows_.count() * w,
                   std::numeric_limits<double>::quiet_NaN());
    parallel_rows(rows_.count(), threads, [&](int cj) {
      const int j = rows_.position(cj);
      for (int ci = 0; ci < cols_.count(); ++ci) {
        const int i = cols_.position(ci);
        if (!field_.is_valid(i, j)) continue;  // stays NaN
        for (std::size_t k = 0; k < w; ++k) coarse_[index(ci, cj, k)] = oracle_.max_elevation(i, j, headings_[k]);
      }
    }, progress);
  }

  void horizons(int i, int j, std::vector<double>& sigma) const {
    if (sweep_) {
      const std::size_t texel = static_cast<std::size_t>(j) * field_.width + i;
      for (std::size_t k = 0; k < headings_.size(); ++k)
        sigma[k] = sweep_max_elevation(field_, i, j, headings_[k], far_[k][texel], march_);
      return;
    }
    if (!subsampled()) {
      for (std::size_t k = 0; k < headings_.size(); ++k) sigma[k] = oracle_.max_elevation(i, j, headings_[k]);
      return;
    }
    const SubsampleAxis::Bracket x = cols_.bracket(i), y = rows_.bracket(j);
    for (std::size_t k = 0; k < headings_.size(); ++k) {
      auto along_row = [&](int cj) {
        const double v0 = coarse_[index(x.c0, cj, k)];
        return x.c1 == x.c0 ? v0 : (1.0 - x.a) * v0 + x.a * coarse_[index(x.c1, cj, k)];
      };
      const double r0 = along_row(y.c0);
      // Non-finite iff a sample with a non-zero weight is (σ is never +∞).
      const double v = y.c1 == y.c0 ? r0 : (1.0 - y.a) * r0 + y.a * along_row(y.c1);
      sigma[k] = std::isfinite(v) ? v : oracle_.max_elevation(i, j, headings_[k]);
    }
  }

 private:
  std::size_t index(int ci, int cj, std::size_t k) const {
    return (static_cast<std::size_t>(cj) * cols_.count() + ci) * headings_.size() + k;
  }

  const HorizonOracle& oracle_;
  const terrain::HeightField& field_;
  const std::vector<Heading>& headings_;
  SubsampleAxis cols_, rows_;
  std::vector<double> coarse_;  // [(cj·count_x + ci)·W + k]
  const MarchOptions& march_;
  bool sweep_;
  std::vector<std::vector<std::uint16_t>> far_;  // sweep: codes per heading, [j·width + i]
};

}  // namespace

ProductBands compute_product(const terrain::HeightField& field, Product product, const ProductOptions& options,
                             const ProgressCallback& progress) {
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
  if (lit) validate(*options.lighting);
  const bool rgb = lit && product == Product::Shaded && options.lighting->colour;

  ProductBands out;
  out.width = field.width;
  out.height = field.height;
  out.bands = product == Product::Horizon ? w_march : rgb ? 3 : 1;
  out.data.assign(static_cast<std::size_t>(out.bands) * field.size(), kNaN);
  if (product == Product::Horizon)
    for (int k = 0; k < w_march; ++k) out.band_names.push_back(horizon_band_name(k, w_march));
  else if (rgb)
    out.band_names = {"red", "green", "blue"};
  else
    out.band_names.emplace_back(product_name(product));
  auto put = [&](int b, int i, int j, double v) {
    out.data[(static_cast<std::size_t>(b) * field.height + j) * field.width + i] = static_cast<float>(v);
  };

  // Sun: the visible disc fraction of every texel, in its own pass (its own march).
  std::vector<float> shadow;
  const bool sun_lit = lit && sky::luminance(options.lighting->sun.dni) > 0.0;
  if (product == Product::Shadow || sun_lit) {
    const glm::dvec3& s = options.lighting->sun.direction;
    const bool alone = product == Product::Shadow;
    shadow = shadow_fraction_field(field, {sky::azimuth_of(s), sky::elevation_of(s)}, sun_shadow_options(options),
                                   [&](double f) {
                                     if (progress) progress(alone ? f : kSunShare * f);
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
  const bool needs_visibility = product == Product::Shaded || product == Product::Irradiance;
  const sh::WedgeOperator* wedge = nullptr;
  std::unique_ptr<SkyShading> uniform_sky;
  std::unique_ptr<LitShading> lighting;
  const bool log_route = options.shaded.mode == ShadingMode::LogBrdf;
  if (needs_visibility) {
    const ShadedOptions& s = options.shaded;
    wedge = &sh::wedge_operator(s.sh_order, s.nlp_order, w_sky, s.wedge);
    if (lit)
      lighting = std::make_unique<LitShading>(*options.lighting, rgb, s.mode, s.sh_order);
    else
      uniform_sky = std::make_unique<SkyShading>(s.mode, s.sh_order, uniform_sky_radiance(), true);
  }
  // Tone map of the lit `shaded` (lighting.h): E → linear display value.
  const double display_per_irradiance =
      lit ? shaded_display_scale(options.shaded, *options.lighting) : 0.0;

  const std::vector<Heading> headings =
      product == Product::Horizon ? geographic_headings(w_march)
      : needs_visibility          ? math_headings(w_sky)
                                  : geographic_headings(w_sky);

  // Raw horizons: with sub-sampling, the coarse texels are marched first.
  HorizonSource horizons(oracle, field, options, headings);
  const double coarse_share = horizons.coarse_share();
  horizons.march_coarse(options.threads, [&](double f) { main_progress(coarse_share * f); });
  horizons.sweep(options.threads, [&](double f) { main_progress(0.5 * f); });
  const double sweep_share = horizons.sweeps() ? 0.5 : 0.0;

  parallel_rows(field.height, options.threads, [&](int j) {
    std::vector<double> sigma(headings.size());
    std::vector<double> scratch, vis, log_vis;
    if (wedge) {
      scratch.resize(static_cast<std::size_t>(wedge->azimuths()) * wedge->nlp_order());
      vis.resize(wedge->rows());
      if (log_route) log_vis.resize(wedge->rows());
    }
    for (int i = 0; i < field.width; ++i) {
      if (!field.is_valid(i, j)) continue;  // stays NaN
      const glm::dvec3 n = horn_normal(field, i, j);
      horizons.horizons(i, j, sigma);
      switch (product) {
        case Product::Horizon:
          for (int k = 0; k < w_march; ++k)
            put(k, i, j, std::max(sigma[k], oracle.ground_floor(j, headings[k])) * 180.0 / std::numbers::pi);
          break;
        case Product::Svf: put(0, i, j, svf_from_horizon(sigma)); break;
        case Product::Skyview: put(0, i, j, skyview_from_horizon(sigma, n)); break;
        case Product::Shaded:
        case Product::Irradiance: {
          // Visibility horizon: floored at the tangent plane (math-notes §10.14).
          for (std::size_t k = 0; k < sigma.size(); ++k)
            sigma[k] = std::clamp(std::max(sigma[k], tangent_plane_floor(n, headings[k])), -std::numbers::pi / 2,
                                  std::numbers::pi / 2);
          if (log_route)
            sh::log_visibility_from_horizon(*wedge, sigma, std::log(sh::kDefaultLogEpsilon), scratch, log_vis);
          else
            sh::visibility_from_horizon(*wedge, sigma, scratch, vis);
          if (!lighting) {
            const double radiance = options.shaded.albedo * uniform_sky->radiance(vis, log_vis, n);
            put(0, i, j, srgb_code_value(radiance * options.shaded.exposure));
            break;
          }
          const double sun = shadow.empty() ? 0.0 : shadow[static_cast<std::size_t>(j) * field.width + i];
          for (int c = 0; c < lighting->channels(); ++c) {
            const double e = lighting->irradiance(c, vis, log_vis, n, sun);
            put(c, i, j, product == Product::Irradiance ? e : srgb_code_value(e * display_per_irradiance));
          }
          break;
        }
        case Product::Shadow: break;  // returned above
      }
    }
  }, [&](double f) { main_progress(coarse_share + sweep_share + (1.0 - coarse_share - sweep_share) * f); });
  return out;
}

SunShadowOptions sun_shadow_options(const ProductOptions& o) {
  SunShadowOptions s;
  s.threads = o.threads;
  s.march.curvature = o.march.curvature;
  s.march.max_distance_m = o.march.max_distance_m;
  if (o.exact) {
    s.horizon = SunHorizon::Exact;
    s.exact = ExactMarch{o.exact_options.step_texels, o.march.max_distance_m, o.march.curvature};
  } else if (o.march.method == HorizonMethod::Sweep) {  // the sun's own sweep knobs; Marched where it cannot
    s.horizon = SunHorizon::Swept;
    s.march.method = HorizonMethod::Sweep;
  }
  return s;
}

Radiance channel_radiance(std::shared_ptr<const sky::SkyModel> sky, bool rgb, int channel) {
  if (rgb) return [sky, channel](const glm::dvec3& d) { return sky->radiance(d)[channel]; };
  return [sky](const glm::dvec3& d) { return sky::luminance(sky->radiance(d)); };
}

double shaded_display_scale(const ShadedOptions& shaded, const Lighting& lighting) {
  return shaded.exposure * kShadedKey * shaded.albedo / lighting.reference_irradiance;
}

Radiance uniform_sky_radiance() {
  return [](const glm::dvec3& d) { return d.z > 0.0 ? 1.0 : 0.0; };
}

std::string horizon_band_name(int k, int azimuths) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "horizon_az%05.1f", 360.0 * k / azimuths);
  return buf;
}

}  // namespace skylit::shading
