#include "terrain/synthetic.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace skylit::terrain {
namespace {

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// 2-D gradient (Perlin) noise in about [−1, 1]; gradients from a hash of the lattice
// point, the octave and the seed.
class GradientNoise {
 public:
  explicit GradientNoise(std::uint64_t seed) : seed_(splitmix64(seed)) {}

  double operator()(double x, double y, int octave) const {
    const double fx = std::floor(x), fy = std::floor(y);
    const auto ix = static_cast<std::int64_t>(fx), iy = static_cast<std::int64_t>(fy);
    const double tx = x - fx, ty = y - fy;
    const double d00 = dot(ix, iy, octave, tx, ty), d10 = dot(ix + 1, iy, octave, tx - 1, ty);
    const double d01 = dot(ix, iy + 1, octave, tx, ty - 1), d11 = dot(ix + 1, iy + 1, octave, tx - 1, ty - 1);
    const double u = fade(tx), v = fade(ty);
    return 1.4142 * ((1 - v) * ((1 - u) * d00 + u * d10) + v * ((1 - u) * d01 + u * d11));
  }

 private:
  static double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }
  double dot(std::int64_t i, std::int64_t j, int octave, double dx, double dy) const {
    const std::uint64_t h = splitmix64(seed_ ^ splitmix64(static_cast<std::uint64_t>(i) * 0x632BE59BD9B4E019ull +
                                                          static_cast<std::uint64_t>(j) * 0x85157AF5ull +
                                                          static_cast<std::uint64_t>(octave)));
    // 16 evenly spaced unit gradients (cos, sin of k·π/8), chosen by the hash.
    static const double g[16][2] = {
        {1, 0}, {0.9238795325112867, 0.3826834323650898}, {0.7071067811865476, 0.7071067811865476},
        {0.3826834323650898, 0.9238795325112867}, {0, 1}, {-0.3826834323650898, 0.9238795325112867},
        {-0.7071067811865476, 0.7071067811865476}, {-0.9238795325112867, 0.3826834323650898}, {-1, 0},
        {-0.9238795325112867, -0.3826834323650898}, {-0.7071067811865476, -0.7071067811865476},
        {-0.3826834323650898, -0.9238795325112867}, {0, -1}, {0.3826834323650898, -0.9238795325112867},
        {0.7071067811865476, -0.7071067811865476}, {0.9238795325112867, -0.3826834323650898}};
    const auto& v = g[h & 15u];
    return v[0] * dx + v[1] * dy;
  }
  std::uint64_t seed_;
};

double smoothstep(double e0, double e1, double x) {
  const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

}  // namespace

HeightField make_synthetic_terrain(const SyntheticOptions& o) {
  if (o.width < 2 || o.height < 2) throw std::invalid_argument("synthetic terrain: size must be at least 2×2");
  if (!(o.spacing > 0) || !(o.feature_size > 0) || !(o.relief >= 0) || o.octaves < 1 || o.octaves > 24 ||
      !(o.ridge_weight >= 0 && o.ridge_weight <= 1) || !(o.valley_width > 0) ||
      !(o.valley_depth >= 0 && o.valley_depth <= 1))
    throw std::invalid_argument("synthetic terrain: invalid options");
  HeightField f(o.width, o.height, o.spacing);
  const GradientNoise noise(o.seed);
  const GradientNoise path_noise(o.seed ^ 0xA5A5A5A5ull);
  const double extent_y = (o.height - 1) * o.spacing;
  std::vector<double> z(f.size());
  double lo = 1e300, hi = -1e300;
  for (int j = 0; j < o.height; ++j) {
    const double y = j * o.spacing;  // metres south of the north edge
    // The valley axis wanders around the middle row: low-frequency noise in x.
    for (int i = 0; i < o.width; ++i) {
      // Domain warp: displacing the lookup by low-frequency noise bends the ridges
      // and valleys into organic shapes instead of a visible lattice.
      const double wf = 1.0 / (1.5 * o.feature_size);
      const double x = i * o.spacing + 0.35 * o.feature_size * noise(i * o.spacing * wf, y * wf, 101);
      const double yw = y + 0.35 * o.feature_size * noise(i * o.spacing * wf + 5.2, y * wf + 1.3, 102);
      double fbm = 0.0, ridged = 0.0, amp = 1.0, norm = 0.0, weight = 1.0;
      double freq = 1.0 / o.feature_size;
      for (int k = 0; k < o.octaves; ++k) {
        fbm += amp * noise(x * freq, yw * freq, k);
        // Ridged multifractal: sharp crests where the noise crosses zero; each octave
        // is weighted by the previous one so detail gathers on the ridges and the
        // valleys between them stay smooth.
        double r = 1.0 - std::abs(noise(x * freq + 31.7, yw * freq - 17.3, k + 64));
        r *= r;
        ridged += amp * r * weight;
        weight = std::clamp(r * 1.8, 0.0, 1.0);
        norm += amp;
        amp *= 0.48;
        freq *= 2.0;
      }
      fbm /= norm;                   // about [−1, 1]
      ridged = ridged / norm;        // about [0, 1]
      double h = (1.0 - o.ridge_weight) * 0.5 * (fbm + 1.0) + o.ridge_weight * ridged;
      // Broad valley floors and steep peaks, as erosion leaves them.
      h = std::pow(std::clamp(h, 0.0, 1.0), 1.6);
      if (o.carve_valley) {
        const double axis = 0.5 * extent_y + 0.18 * extent_y * path_noise(x / (2.5 * o.feature_size), 0.37, 0);
        const double d = std::abs(y - axis);
        // Flat floor, then walls rising smoothly to the untouched terrain.
        const double carve = 1.0 - smoothstep(0.3 * o.valley_width, 2.5 * o.valley_width, d);
        // Pull the terrain toward a floor slightly above the lowest noise values;
        // a little of the original relief survives as texture on the floor.
        h -= o.valley_depth * carve * (0.9 * h - 0.02);
      }
      z[static_cast<std::size_t>(j) * o.width + i] = h;
      lo = std::min(lo, h);
      hi = std::max(hi, h);
    }
  }
  const double range = hi > lo ? hi - lo : 1.0;
  for (std::size_t k = 0; k < z.size(); ++k)
    f.heights[k] = static_cast<float>(o.base_height + o.relief * (z[k] - lo) / range);
  return f;
}

HeightField default_scene() { return make_synthetic_terrain(SyntheticOptions{}); }

}  // namespace skylit::terrain
