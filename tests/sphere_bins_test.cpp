// Sphere bins (shading/blockers/sphere_bins.h) are conservative: every texel where a
// group's cull bound exceeds budget/N (N groups; a receiver may keep it, receiver_budget.h)
// lies in a tile listing the group, and every texel whose sun ray passes within a
// sphere's reach in one listing the sphere — checked by brute force over every texel and
// group or sphere, on a projected grid and on rows of unequal spacing (a geographic DEM).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "shading/blocker_frame.h"
#include "shading/reference_pipeline.h"
#include "shading/blockers/disc_occlusion.h"
#include "shading/blockers/receiver_budget.h"
#include "shading/blockers/sphere_bins.h"
#include "terrain/synthetic.h"

namespace skylit::blockers {
namespace {

bool listed(std::span<const std::uint32_t> list, std::uint32_t k) {
  return std::find(list.begin(), list.end(), k) != list.end();
}

terrain::HeightField field(bool geographic) {
  terrain::SyntheticOptions o;
  o.width = 160;
  o.height = 130;
  o.spacing = 3.0;
  o.relief = 40.0;
  o.feature_size = 200.0;
  terrain::HeightField f = terrain::make_synthetic_terrain(o);
  if (geographic)  // rows narrowing northward, as on a lat/lon grid
    for (int j = 0; j < f.height; ++j) f.dx_per_row[j] = 3.0 * (0.6 + 0.4 * j / (f.height - 1.0));
  return f;
}

TEST(SphereBins, EveryTexelASphereReachesIsInItsTile) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (bool geographic : {false, true}) {
    const terrain::HeightField f = field(geographic);
    const double top = *std::max_element(f.heights.begin(), f.heights.end());
    std::vector<Sphere> spheres;
    for (int k = 0; k < 12; ++k)
      spheres.push_back({{u(rng) * 500 - 20, -(u(rng) * 400 - 20), top + 10 + u(rng) * 60}, 1.0 + 3.0 * u(rng)});
    shading::ProductOptions o;
    o.blockers.blocker.cull_error = 0.02;  // reaches of tens of metres: some tiles list nothing
    const glm::dvec3 sun = glm::normalize(glm::dvec3(0.4, -0.3, 0.6));
    shading::LightingRequest r;
    o.lighting = shading::resolve_lighting(r, std::nullopt).lighting;
    o.lighting->sun.direction = sun;
    const SphereGroups groups = group_spheres(spheres, 60.0);
    EXPECT_LT(groups.size(), spheres.size()) << "some spheres share a group";
    const SkyBlockingOptions frame = shading::frame_blocking(o);
    const SphereBins bins = shading::frame_bins(f, spheres, groups, frame, o);
    const double share = frame.blocker.cull_error / static_cast<double>(groups.size());
    const double disc = shading::sun_shadow_options(o).radius;
    int sky_pairs = 0, sun_pairs = 0;
    for (int j = 0; j < f.height; ++j)
      for (int i = 0; i < f.width; ++i) {
        const glm::dvec3 p(i * f.dx(j), -j * f.dy, f.at(i, j));
        for (std::uint32_t g = 0; g < groups.size(); ++g) {
          const glm::dvec3 toward = glm::normalize(groups.group(g).centre - p);  // never below the plane
          if (node_cull_bound(groups.group(g), p, toward, o.shaded.sh_order) > share) {
            ++sky_pairs;
            EXPECT_TRUE(listed(bins.sky(i, j), g)) << geographic << " sky " << i << "," << j << " group " << g;
          }
        }
        for (std::uint32_t k = 0; k < spheres.size(); ++k) {
          const Sphere& s = spheres[k];
          // The sun: any ray of the disc (its axis widened by the disc radius) meeting the sphere.
          const Sphere grown{s.centre, s.radius + glm::length(s.centre - p) * std::tan(disc)};
          if (ray_hits_sphere(grown, p, sun)) {
            ++sun_pairs;
            EXPECT_TRUE(listed(bins.sun(i, j), k)) << geographic << " sun " << i << "," << j << " sphere " << k;
          }
        }
      }
    std::printf("%s: %d sky and %d sun pairs, %d of %d tiles list a sky sphere\n", geographic ? "geographic" : "projected",
                sky_pairs, sun_pairs, bins.sky_tiles(), bins.tiles_x() * bins.tiles_y());
    EXPECT_GT(sky_pairs, 1000) << geographic;
    EXPECT_GT(sun_pairs, 20) << geographic;
    // Bins are not the whole field: the disc of reach, not every tile.
    EXPECT_LT(bins.sky_tiles(), bins.tiles_x() * bins.tiles_y()) << geographic;
  }
}

}  // namespace
}  // namespace skylit::blockers
