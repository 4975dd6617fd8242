#include "shading/sun_light.h"

#include "shading/horizon/azimuth.h"
#include "shading/horizon/horizon_ray.h"
#include "shading/horizon/horizon_sweep.h"
#include "shading/horizon/surface_normals.h"
#include "parallel/parallel_rows.h"
#include "shading/sky/sun_disc.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>

namespace skylit::shading {
namespace {

constexpr double kHalfPi = std::numbers::pi / 2;

// Up to kMaxPolylinePoints horizon samples across the disc, x ascending in [−1, 1].
struct Columns {
  std::array<double, sky::kMaxPolylinePoints> x{}, y{};
  int n = 0;
};

// −∞ (no step on the grid) and anything past the poles become finite elevations.
double finite_elevation(double sigma) { return std::clamp(sigma, -kHalfPi, kHalfPi); }

// The marcher's horizon; for a level-0 plain-max march (the sun's default) a running max
// of slopes and one atan on the marcher's own schedule and geometry, because
// HorizonMarcher::max_elevation buffers every blocking angle (on the heap past 64 steps,
// and k_v = 32 takes ~300).
double marched_elevation(const terrain::HeightField& f, const horizon::HorizonMarcher& m, int i, int j,
                         horizon::Heading u) {
  const horizon::MarchOptions& o = m.options();
  if (o.use_pyramid || o.smooth_max) return m.max_elevation(i, j, u);
  const double h0 = f.at(i, j);
  double best = -std::numeric_limits<double>::infinity();
  for (int s = 0; s < m.steps(); ++s) {
    const double t = m.distance(s);
    const horizon::GridPoint p = horizon::ray_point(f, i, j, u, t);
    if (!horizon::on_grid(f, p)) break;
    best = std::max(best, (horizon::bilinear_height(f, p) - o.curvature.drop(t) - h0) / t);
  }
  return std::isinf(best) ? best : std::atan(best);
}

// Linear interpolation of the W product-azimuth horizons of one texel, marching each
// band once, on demand (cache sized W, owned by the row).
class BandHorizons {
 public:
  BandHorizons(const terrain::HeightField& field, const horizon::HorizonMarcher& marcher, int azimuths)
      : field_(field), marcher_(marcher), w_(azimuths), sigma_(azimuths) {
    done_.assign(azimuths, 0);
  }
  void reset() { std::fill(done_.begin(), done_.end(), 0); }
  // Band coordinate of a geographic azimuth: A / (2π/W).
  double band_coord(double azimuth) const { return azimuth * w_ / horizon::kTwoPi; }
  double at(int i, int j, double band) {
    const double k0 = std::floor(band);
    const double f = band - k0;
    return (1.0 - f) * sigma(i, j, static_cast<long long>(k0)) + f * sigma(i, j, static_cast<long long>(k0) + 1);
  }

 private:
  double sigma(int i, int j, long long k) {
    const int b = static_cast<int>(((k % w_) + w_) % w_);
    if (!done_[b]) {
      sigma_[b] = finite_elevation(
          marched_elevation(field_, marcher_, i, j, horizon::heading_from_geographic(horizon::band_azimuth(b, w_))));
      done_[b] = 1;
    }
    return sigma_[b];
  }
  const terrain::HeightField& field_;
  const horizon::HorizonMarcher& marcher_;
  int w_;
  std::vector<double> sigma_;
  std::vector<char> done_;
};

}  // namespace

horizon::MarchOptions sun_march_options() {
  horizon::MarchOptions o;
  o.k_v = 32;
  o.use_pyramid = false;
  o.smooth_max = false;
  o.sweep_near_steps = 8;
  o.sweep_lines = 3;
  return o;
}

void validate(const SunShadowOptions& o) {
  validate(o.march);
  if (!(o.radius > 0.0 && o.radius < std::numbers::pi / 4))
    throw std::invalid_argument("sun shadow: disc radius must be in (0, π/4)");
  if (o.horizon == SunHorizon::Exact) {
    if (o.exact_columns < 2 || o.exact_columns > sky::kMaxPolylinePoints)
      throw std::invalid_argument("sun shadow: exact columns must be in [2, 65]");
    if (!(o.exact.step_texels > 0.0) || !(o.exact.max_distance_m >= 0.0))
      throw std::invalid_argument("sun shadow: exact step must be > 0, max distance ≥ 0");
  }
}

double sun_sweep_floor(double elevation, const SunShadowOptions& options) {
  const double floor = elevation - options.radius - kSunFloorMargin;
  return elevation >= kSunFloorMinElevation && floor < kHalfPi ? std::tan(floor)
                                                                : -std::numeric_limits<double>::infinity();
}

bool sun_sweeps(const terrain::HeightField& field, const SunShadowOptions& options) {
  return options.horizon == SunHorizon::Swept && horizon::sweep_applicable(field, options.march);
}

glm::dvec3 sun_direction(SunAngles sun) {
  const double ce = std::cos(sun.elevation);
  return {ce * std::sin(sun.azimuth), ce * std::cos(sun.azimuth), std::sin(sun.elevation)};
}

std::vector<float> shadow_fraction_field(const terrain::HeightField& field, SunAngles sun,
                                         const SunShadowOptions& options, const ProgressCallback& progress) {
  validate(options);
  if (!std::isfinite(sun.azimuth) || !std::isfinite(sun.elevation) || std::abs(sun.elevation) > kHalfPi)
    throw std::invalid_argument("sun shadow: sun azimuth/elevation must be finite, |elevation| ≤ π/2");
  const double r = options.radius, e_s = sun.elevation;
  // Azimuth half-width of the disc: column x sits at A_s + x·half_width.
  const double half_width = r / sky::disc_azimuth_scale(e_s, r);
  // Swept where the sweep applies (the sun's far slopes first, one heading), else Marched.
  const bool swept = sun_sweeps(field, options);
  const SunHorizon horizon = options.horizon == SunHorizon::Swept && !swept ? SunHorizon::Marched : options.horizon;
  std::unique_ptr<horizon::HorizonMarcher> marcher;
  if (horizon == SunHorizon::Marched || horizon == SunHorizon::Interpolated)
    marcher = std::make_unique<horizon::HorizonMarcher>(field, options.march);
  std::vector<std::uint16_t> far;  // codes (horizon_sweep.h)
  if (swept)
    far = horizon::sweep_far_slopes(field, horizon::heading_from_geographic(sun.azimuth), options.march, options.threads,
                                    sun_sweep_floor(e_s, options));

  std::vector<float> out(field.size(), std::numeric_limits<float>::quiet_NaN());
  auto march_at = [&](int i, int j, double x) {
    const horizon::Heading u = horizon::heading_from_geographic(sun.azimuth + x * half_width);
    if (horizon == SunHorizon::Swept)  // x = 0 only
      return finite_elevation(horizon::sweep_max_elevation(
          field, i, j, u, far[static_cast<std::size_t>(j) * field.width + i], options.march));
    return finite_elevation(horizon == SunHorizon::Exact ? horizon::exact_max_elevation(field, i, j, u, options.exact)
                                                         : marched_elevation(field, *marcher, i, j, u));
  };

  parallel::parallel_rows(field.height, options.threads, [&](int j) {
    std::unique_ptr<BandHorizons> bands;
    if (options.horizon == SunHorizon::Interpolated)
      bands = std::make_unique<BandHorizons>(field, *marcher, options.march.azimuths);
    Columns c;
    for (int i = 0; i < field.width; ++i) {
      if (!field.is_valid(i, j)) continue;
      const sky::DiscLine tangent = sky::tangent_plane_line(horizon::horn_normal(field, i, j), sun.azimuth, e_s, r);
      float& result = out[static_cast<std::size_t>(j) * field.width + i];
      if (tangent.offset <= -1.0) {  // the whole disc is behind the surface: no march
        result = 0.0f;
        continue;
      }
      c.n = 0;
      auto push = [&](double x, double sigma) {
        c.x[c.n] = x;
        c.y[c.n] = (sigma - e_s) / r;
        ++c.n;
      };
      switch (horizon) {
        case SunHorizon::Swept:  // the sun's azimuth only: a level line across the disc
        case SunHorizon::Marched:
          if (horizon == SunHorizon::Marched && options.disc_slope) {
            for (double x : {-1.0, 0.0, 1.0}) push(x, march_at(i, j, x));
          } else {
            const double s = march_at(i, j, 0.0);
            push(-1.0, s);
            push(1.0, s);
          }
          break;
        case SunHorizon::Exact:
          for (int k = 0; k < options.exact_columns; ++k) {
            const double x = -1.0 + 2.0 * k / (options.exact_columns - 1);
            push(x, march_at(i, j, x));
          }
          break;
        case SunHorizon::Interpolated: {
          bands->reset();
          // The interpolant is linear between band azimuths: sample the disc's edges and
          // every band azimuth in between (uniformly if there are too many).
          const double b_lo = bands->band_coord(sun.azimuth - half_width);
          const double b_hi = bands->band_coord(sun.azimuth + half_width);
          const double first = std::floor(b_lo) + 1.0, last = std::ceil(b_hi) - 1.0;
          const bool exact_kinks = last - first + 3.0 <= sky::kMaxPolylinePoints;
          const int n = exact_kinks ? static_cast<int>(std::max(last - first + 1.0, 0.0)) + 2 : sky::kMaxPolylinePoints;
          for (int k = 0; k < n; ++k) {
            double b = 0.0;
            if (k == 0) b = b_lo;
            else if (k == n - 1) b = b_hi;
            else b = exact_kinks ? first + (k - 1) : b_lo + (b_hi - b_lo) * k / (n - 1);
            const double x = b_hi > b_lo ? -1.0 + 2.0 * (b - b_lo) / (b_hi - b_lo) : 0.0;
            push(std::clamp(x, -1.0, 1.0), bands->at(i, j, b));
          }
          c.x[0] = -1.0;
          c.x[n - 1] = 1.0;
          break;
        }
      }
      result = static_cast<float>(sky::disc_fraction_above_polyline({c.x.data(), static_cast<std::size_t>(c.n)},
                                                               {c.y.data(), static_cast<std::size_t>(c.n)}, &tangent));
    }
  }, progress);
  return out;
}

double sun_irradiance(const glm::dvec3& n, const glm::dvec3& s, double dni, double fraction) {
  return dni * std::max(n.x * s.x + n.y * s.y + n.z * s.z, 0.0) * fraction;
}

sky::Rgb sun_irradiance(const glm::dvec3& n, const sky::Sun& sun, double fraction) {
  return sun.dni * sun_irradiance(n, sun.direction, 1.0, fraction);
}

}  // namespace skylit::shading
