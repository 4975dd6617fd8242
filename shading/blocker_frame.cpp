#include "shading/blocker_frame.h"

#include "shading/blockers/disc_occlusion.h"
#include "shading/reference_pipeline.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace skylit::shading {
namespace {

std::optional<glm::dvec3> sun_of(const ProductOptions& options) {
  if (!options.lighting) return std::nullopt;
  return options.lighting->sun.direction;
}

}  // namespace

blockers::ReceiverGrid receiver_grid(const terrain::HeightField& field) {
  blockers::ReceiverGrid g{field.width, field.height, 0.0, field.dy, 0.0, 0.0};
  g.dx_min = field.dx_per_row.empty() ? 0.0 : field.dx_per_row.front();
  for (double dx : field.dx_per_row) {
    g.dx = std::max(g.dx, dx);
    g.dx_min = std::min(g.dx_min, dx);
  }
  const auto [lo, hi] = std::minmax_element(field.heights.begin(), field.heights.end());
  g.z_min = *lo;
  g.z_max = *hi;
  return g;
}

blockers::SkyBlockingOptions frame_blocking(const ProductOptions& options) {
  blockers::SkyBlockingOptions b = options.blockers;
  if (options.exact) b.blocker.cull_error = kTruthCullError;
  return b;
}

blockers::SphereBins frame_bins(const terrain::HeightField& field, std::span<const blockers::Sphere> spheres,
                                const blockers::SphereGroups& groups, const blockers::SkyBlockingOptions& blocking,
                                const ProductOptions& options) {
  return blockers::SphereBins(spheres, groups, receiver_grid(field), options.shaded.sh_order, blocking.blocker,
                              sun_of(options), sun_shadow_options(options).radius);
}

BlockerFrame::BlockerFrame(const terrain::HeightField& field, std::span<const blockers::Sphere> spheres,
                           const ProductOptions& options)
    : field_(field),
      spheres_(spheres),
      options_(options),
      blocking_(frame_blocking(options)),
      disc_radius_(sun_shadow_options(options).radius),
      groups_(blockers::group_spheres(spheres)),
      bins_(frame_bins(field, spheres, groups_, blocking_, options)) {
  blockers::validate(options.blockers.blocker);
}

glm::dvec3 BlockerFrame::position(int i, int j) const { return {i * field_.dx(j), -j * field_.dy, field_.at(i, j)}; }

double BlockerFrame::sun_left(int i, int j, const glm::dvec3& sun) const {
  const std::span<const std::uint32_t> near = bins_.sun(i, j);
  if (near.empty()) return 1.0;
  if (!options_.exact) return blockers::disc_fraction_left(spheres_, near, position(i, j), sun, disc_radius_);
  std::vector<blockers::Sphere> listed;
  for (std::uint32_t k : near) listed.push_back(spheres_[k]);
  return blockers::disc_fraction_sampled(listed, position(i, j), sun, disc_radius_, kTruthDiscSamples);
}

int BlockerFrame::sky_delta(int i, int j, const glm::dvec3& normal, std::span<const double> sigma,
                            std::span<const double> vis_t, std::span<const double> log_t, std::span<double> delta,
                            std::span<double> log_sum, std::span<double> scratch) const {
  const blockers::Receiver r{position(i, j), normal, sigma, vis_t, log_t};
  return blockers::block_sky(spheres_, groups_, bins_.sky(i, j), r, blocking_, delta, log_sum, scratch);
}

Occluders BlockerFrame::occluders(int i, int j, std::span<const double> sigma, bool with_caps, double floor_at) const {
  Occluders occ;
  const int w = static_cast<int>(sigma.size());
  std::vector<double> samples(sigma.begin(), sigma.end());
  // Piecewise constant: each sample holds the sector centred on its azimuth 2πk/W.
  occ.horizon = [samples, w, floor_at](double phi) {
    const int k = static_cast<int>(std::lround(phi * w / (2.0 * std::numbers::pi)));
    return std::max(samples[((k % w) + w) % w], floor_at);
  };
  if (!with_caps) return occ;
  const glm::dvec3 p = position(i, j);
  std::vector<std::uint32_t> members;  // the truth takes every sphere of a listed group
  for (std::uint32_t g : bins_.sky(i, j))
    for (std::uint32_t m = 0; m < groups_.group(g).count; ++m) members.push_back(groups_.order[groups_.group(g).first + m]);
  for (std::uint32_t k : members) {
    const blockers::Sphere& s = spheres_[k];
    const glm::dvec3 to_c = s.centre - p;
    const double d = glm::length(to_c);
    if (d <= s.radius) {  // inside: the hemisphere toward the centre (or above, at it)
      occ.caps.push_back({d > 0.0 ? to_c / d : glm::dvec3(0, 0, 1), std::numbers::pi / 2});
      continue;
    }
    occ.caps.push_back({to_c / d, std::asin(s.radius / d)});
  }
  return occ;
}

int BlockerFrame::truth_azimuths(const std::vector<Cap>& caps) const {
  // Eight azimuth steps across the narrowest cap, within [2048, 65536] (a cap narrower
  // than 2π/65536/8 rad changes no product by more than ~1e-9).
  double narrowest = std::numbers::pi / 2;
  for (const Cap& c : caps) narrowest = std::min(narrowest, c.half_angle);
  const double wanted = std::ceil(8.0 * std::numbers::pi / std::max(narrowest, 1e-9));
  const double base = std::max(2048, options_.exact_options.sky_azimuths);
  return static_cast<int>(std::clamp(wanted, base, 65536.0));
}

void BlockerFrame::exact_sky_delta(int i, int j, std::span<const double> sigma, std::span<double> delta) const {
  const int order = sh::order_of(delta.size());
  const Occluders with = occluders(i, j, sigma, true, -std::numbers::pi / 2);
  const Occluders without = occluders(i, j, sigma, false, -std::numbers::pi / 2);
  IntegrationOptions opt;
  opt.azimuths = truth_azimuths(with.caps);
  const sh::Vec a = project_visibility(order, with, opt), b = project_visibility(order, without, opt);
  for (std::size_t q = 0; q < delta.size(); ++q) delta[q] = a[q] - b[q];
}

double BlockerFrame::exact_skyview_delta(int i, int j, const glm::dvec3& normal, std::span<const double> sigma) const {
  // The uniform sky exists only above the horizontal: horizons floored at 0.
  const Occluders with = occluders(i, j, sigma, true, 0.0);
  const Occluders without = occluders(i, j, sigma, false, 0.0);
  const int w = truth_azimuths(with.caps);
  return cosine_weighted_visibility(with, normal, w) - cosine_weighted_visibility(without, normal, w);
}

int BlockerFrame::below_ground(const terrain::HeightField& field, std::span<const blockers::Sphere> spheres) {
  int n = 0;
  for (const blockers::Sphere& s : spheres) {
    const int j = static_cast<int>(std::lround(-s.centre.y / field.dy));
    if (j < 0 || j >= field.height) continue;
    const int i = static_cast<int>(std::lround(s.centre.x / field.dx(j)));
    if (i < 0 || i >= field.width) continue;
    n += s.centre.z < field.at(i, j) ? 1 : 0;
  }
  return n;
}

}  // namespace skylit::shading
