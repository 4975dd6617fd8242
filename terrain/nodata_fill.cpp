#include "terrain/nodata_fill.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <deque>
#include <stdexcept>
#include <vector>

namespace skylit::terrain {
namespace {

struct Grid {
  int w = 0, h = 0;
  std::vector<double> z;
  std::vector<std::uint8_t> known;  // fixed (valid) texels
};

// Gauss–Seidel sweeps of z = mean of the in-grid 4-neighbours over the unknown texels,
// until the largest change is below `tol` or `max_sweeps` is reached.
void relax(Grid& g, int max_sweeps, double tol) {
  std::vector<std::size_t> unknown;
  for (std::size_t k = 0; k < g.z.size(); ++k)
    if (!g.known[k]) unknown.push_back(k);
  if (unknown.empty()) return;
  for (int sweep = 0; sweep < max_sweeps; ++sweep) {
    double max_change = 0.0;
    for (std::size_t k : unknown) {
      const int i = static_cast<int>(k % g.w), j = static_cast<int>(k / g.w);
      double sum = 0.0;
      int n = 0;  // zero gradient across the grid edge: missing neighbours are skipped
      if (i > 0) sum += g.z[k - 1], ++n;
      if (i + 1 < g.w) sum += g.z[k + 1], ++n;
      if (j > 0) sum += g.z[k - g.w], ++n;
      if (j + 1 < g.h) sum += g.z[k + g.w], ++n;
      if (n == 0) continue;
      const double v = sum / n;
      max_change = std::max(max_change, std::abs(v - g.z[k]));
      g.z[k] = v;
    }
    if (max_change < tol) break;
  }
}

// One push step: 2×2 blocks → one texel, the mean of the known children.
Grid coarsen(const Grid& f) {
  Grid c;
  c.w = (f.w + 1) / 2;
  c.h = (f.h + 1) / 2;
  c.z.assign(static_cast<std::size_t>(c.w) * c.h, 0.0);
  c.known.assign(c.z.size(), 0);
  for (int j = 0; j < c.h; ++j)
    for (int i = 0; i < c.w; ++i) {
      double sum = 0.0;
      int n = 0;
      for (int dj = 0; dj < 2; ++dj)
        for (int di = 0; di < 2; ++di) {
          const int fi = 2 * i + di, fj = 2 * j + dj;
          if (fi >= f.w || fj >= f.h) continue;
          const std::size_t k = static_cast<std::size_t>(fj) * f.w + fi;
          if (f.known[k]) sum += f.z[k], ++n;
        }
      if (n > 0) {
        const std::size_t k = static_cast<std::size_t>(j) * c.w + i;
        c.z[k] = sum / n;
        c.known[k] = 1;
      }
    }
  return c;
}

void solve(Grid& g) {
  const bool all_known = std::all_of(g.known.begin(), g.known.end(), [](auto v) { return v != 0; });
  if (all_known) return;
  if (g.w > 1 || g.h > 1) {
    Grid c = coarsen(g);
    solve(c);
    // Pull: unknown fine texels start from their parent's value.
    for (int j = 0; j < g.h; ++j)
      for (int i = 0; i < g.w; ++i) {
        const std::size_t k = static_cast<std::size_t>(j) * g.w + i;
        if (!g.known[k]) g.z[k] = c.z[static_cast<std::size_t>(j / 2) * c.w + i / 2];
      }
  }
  // Coarse levels are cheap: converge them well; fine levels only need to smooth
  // the blockiness of the pulled start, which decays fast at their own scale.
  const bool coarse = static_cast<std::size_t>(g.w) * g.h <= 4096;
  relax(g, coarse ? 2000 : 100, 1e-4);
}

}  // namespace

void fill_laplace(std::span<float> heights, std::span<const std::uint8_t> valid, int width,
                  int height) {
  if (width < 1 || height < 1 || heights.size() != static_cast<std::size_t>(width) * height ||
      valid.size() != heights.size())
    throw std::invalid_argument("fill_laplace: grid size mismatch");
  Grid g;
  g.w = width;
  g.h = height;
  g.z.assign(heights.begin(), heights.end());
  g.known.assign(valid.begin(), valid.end());
  if (std::none_of(g.known.begin(), g.known.end(), [](auto v) { return v != 0; }))
    throw std::invalid_argument("fill_laplace: no valid texel to fill from");
  solve(g);
  for (std::size_t k = 0; k < heights.size(); ++k)
    if (!valid[k]) heights[k] = static_cast<float>(g.z[k]);
}

void fill_nearest(std::span<float> heights, std::span<const std::uint8_t> valid, int width,
                  int height) {
  if (width < 1 || height < 1 || heights.size() != static_cast<std::size_t>(width) * height ||
      valid.size() != heights.size())
    throw std::invalid_argument("fill_nearest: grid size mismatch");
  std::vector<std::uint8_t> done(valid.begin(), valid.end());
  std::deque<std::size_t> queue;
  for (std::size_t k = 0; k < done.size(); ++k)
    if (done[k]) queue.push_back(k);
  if (queue.empty()) throw std::invalid_argument("fill_nearest: no valid texel to fill from");
  // Multi-source BFS: each void inherits the height of the wave front that reached it.
  while (!queue.empty()) {
    const std::size_t k = queue.front();
    queue.pop_front();
    const int i = static_cast<int>(k % width), j = static_cast<int>(k / width);
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        const int ni = i + di, nj = j + dj;
        if (ni < 0 || nj < 0 || ni >= width || nj >= height) continue;
        const std::size_t n = static_cast<std::size_t>(nj) * width + ni;
        if (done[n]) continue;
        done[n] = 1;
        heights[n] = heights[k];
        queue.push_back(n);
      }
  }
}

void fill_constant(std::span<float> heights, std::span<const std::uint8_t> valid, float value) {
  if (valid.size() != heights.size()) throw std::invalid_argument("fill_constant: size mismatch");
  for (std::size_t k = 0; k < heights.size(); ++k)
    if (!valid[k]) heights[k] = value;
}

}  // namespace skylit::terrain
