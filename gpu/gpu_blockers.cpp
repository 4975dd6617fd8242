#include "gpu/gpu_blockers.h"

#include "shading/blocker_frame.h"
#include "shading/blockers/cap_log_table.h"
#include "shading/blockers/disc_occlusion.h"
#include "shading/blockers/receiver_budget.h"
#include "shading/reference_pipeline.h"
#include "shading/sh/sh_rotation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace skylit::gpu {
namespace {

// Offsets (counting from the first index) then indices, as sphere_blockers.glsl reads
// them: floats, exact below 2^24.
std::vector<float> packed(const blockers::SphereBins::Flat& flat) {
  if (flat.offsets.back() + flat.offsets.size() >= (std::size_t{1} << 24))
    throw std::runtime_error("GPU sphere blockers: over 2^24 binned spheres in one frame");
  std::vector<float> out(flat.offsets.begin(), flat.offsets.end());
  out.insert(out.end(), flat.indices.begin(), flat.indices.end());
  return out;
}

// Replaces `buffer` by `values` (one zero texel when empty: GL wants non-empty buffers)
// and `texture` by its view; the view goes first. Returns the bytes uploaded.
std::size_t view(Buffer& buffer, BufferTexture& texture, std::vector<float> values, TextureFormat format) {
  if (values.empty()) values.assign(format == TextureFormat::R32F ? 1 : 4, 0.0f);
  texture = BufferTexture();
  buffer = Buffer::from(std::span<const float>(values));
  texture = BufferTexture(buffer, format);
  return buffer.size_bytes();
}

// Runs of tiles whose sky (or sun) bins list a sphere, along each row of tiles, as texel
// rectangles clipped to the field.
std::vector<terrain::PixelRect> busy_rects(const blockers::SphereBins& bins, const terrain::HeightField& field, bool sky) {
  auto busy = [&](int tx, int ty) {
    const int i = tx * blockers::kBinTexels, j = ty * blockers::kBinTexels;
    return !(sky ? bins.sky(i, j) : bins.sun(i, j)).empty();
  };
  std::vector<terrain::PixelRect> out;
  for (int ty = 0; ty < bins.tiles_y(); ++ty)
    for (int tx = 0; tx < bins.tiles_x();) {
      if (!busy(tx, ty)) {
        ++tx;
        continue;
      }
      const int first = tx;
      while (tx < bins.tiles_x() && busy(tx, ty)) ++tx;
      const int x0 = first * blockers::kBinTexels, y0 = ty * blockers::kBinTexels;
      out.push_back({x0, y0, std::min(tx * blockers::kBinTexels, field.width) - x0,
                     std::min(y0 + blockers::kBinTexels, field.height) - y0});
    }
  return out;
}

// CapLogTable::first_slope per l, scaled as the table (sh::zh_rotation_factor): the
// small caps' log* without a table read.
std::vector<double> cap_log_slopes(const shading::ProductOptions& options) {
  const int order = options.shaded.sh_order;
  const blockers::CapLogTable& table = blockers::cap_log_table(order, options.blockers.blocker.log_clip);
  std::vector<double> slopes;
  for (int l = 0; l < order; ++l) slopes.push_back(sh::zh_rotation_factor(l) * table.first_slope(l));
  return slopes;
}

}  // namespace

std::optional<std::string> gpu_lacks_blockers(shading::Product product, const shading::ProductOptions& options) {
  if (!shading::traits(product).blocked) return std::nullopt;
  const blockers::SkyBlockingOptions& b = options.blockers;
  if (options.exact) return "the GPU has no exact truth for sphere blockers (the reference has: --exact)";
  if (b.blocker.log != blockers::CapLog::kProductAlgebra)
    return "the GPU shades sphere blockers with the log* caps only (the reference has the pointwise log)";
  if (b.composition != blockers::Composition::kProduct && options.shaded.mode != shading::ShadingMode::LogBrdf)
    return "the GPU composes sphere blockers by the SH product only (the reference has the others)";
  if (b.hyb.base != sh::HybBase::kTaylor2 || !b.hyb.renormalise)
    return "the GPU's HYB for sphere blockers needs the PS2 base with renormalisation";
  if (!b.horizon_cull) return "the GPU always culls sphere blockers below the horizon";
  return std::nullopt;
}

void add_blocker_defines(const shading::ProductOptions& options, const BlockerBindings& bindings, bool sky,
                         GlslDefines& d) {
  d.set("SPHERES_UNIT", bindings.spheres)
      .set("SKY_BINS_UNIT", bindings.sky_bins)
      .set("SUN_BINS_UNIT", bindings.sun_bins)
      .set("BIN_TEXELS", blockers::kBinTexels)
      .set("DISC_UNION_SAMPLES", blockers::kDiscUnionSamples)
      .set("DISC_RADIUS", shading::sun_shadow_options(options).radius);
  if (sky)
    d.set("GROUPS_UNIT", bindings.groups)
        .set("ORDER_UNIT", bindings.order)
        .set("MERGE_SIN", options.blockers.merge_sin)
        .set("CAP_LOG_UNIT", bindings.cap_log)
        .set("CAP_LOG_ENTRIES", blockers::CapLogTable::kEntries)
        .set("NEAR_BOUNDS", blockers::kNearBounds)
        .set("MAX_RANKED_GROUPS", blockers::kMaxRankedGroups)
        .set_literal("CAP_LOG_SLOPE", glsl_float_array_literal(cap_log_slopes(options)));
}

GpuBlockers::GpuBlockers(const shading::ProductOptions& options, const BlockerBindings& bindings, bool sky)
    : bindings_(bindings) {
  std::vector<float> values;  // the sun alone needs no table
  if (sky) {
    const int order = options.shaded.sh_order;
    const blockers::CapLogTable& table = blockers::cap_log_table(order, options.blockers.blocker.log_clip);
    for (int e = 0; e < table.entries(); ++e)
      for (int l = 0; l < order; ++l)  // scaled as sh::add_rotated_zh scales a ZH
        values.push_back(
            static_cast<float>(sh::zh_rotation_factor(l) * table.values()[static_cast<std::size_t>(e) * order + l]));
  }
  view(cap_log_, cap_log_tex_, std::move(values), TextureFormat::R32F);
}

std::size_t GpuBlockers::upload(const terrain::HeightField& field, std::span<const blockers::Sphere> spheres,
                                const shading::ProductOptions& options) {
  const blockers::SkyBlockingOptions blocking = shading::frame_blocking(options);
  const blockers::SphereGroups groups = blockers::group_spheres(spheres);
  const blockers::SphereBins bins = shading::frame_bins(field, spheres, groups, blocking, options);
  // Per tree node two texels: (centre, bound) and (area, first, count, next); the member
  // order. The sky bins list each group's root node.
  if (groups.nodes.size() >= (std::size_t{1} << 24))
    throw std::runtime_error("GPU sphere blockers: over 2^24 sphere tree nodes in one frame");
  std::vector<float> packed_groups, packed_spheres;
  for (const blockers::SphereGroup& g : groups.nodes)
    for (double v : {g.centre.x, g.centre.y, g.centre.z, g.bound, g.area, static_cast<double>(g.first),
                     static_cast<double>(g.count), static_cast<double>(g.next)})
      packed_groups.push_back(static_cast<float>(v));
  blockers::SphereBins::Flat sky = bins.flat_sky();
  for (std::uint32_t& g : sky.indices) g = groups.roots[g];
  for (const blockers::Sphere& s : spheres)
    for (double v : {s.centre.x, s.centre.y, s.centre.z, s.radius}) packed_spheres.push_back(static_cast<float>(v));
  const std::size_t bytes = view(spheres_, spheres_tex_, packed_spheres, TextureFormat::RGBA32F) +
                            view(groups_, groups_tex_, packed_groups, TextureFormat::RGBA32F) +
                            view(order_, order_tex_, {groups.order.begin(), groups.order.end()}, TextureFormat::R32F) +
                            view(sky_bins_, sky_bins_tex_, packed(sky), TextureFormat::R32F) +
                            view(sun_bins_, sun_bins_tex_, packed(bins.flat_sun()), TextureFormat::R32F);
  tiles_x_ = bins.tiles_x();
  tiles_ = bins.tiles_x() * bins.tiles_y();
  sky_rects_ = busy_rects(bins, field, true);
  sun_rects_ = busy_rects(bins, field, false);
  // Each receiver's budget for the groups its bin lists (receiver_budget.h).
  cull_budget_ = blocking.blocker.cull_error;
  group_count_ = static_cast<int>(groups.size());
  ratio_attenuation_ = blocking.blocker.ratio_attenuation;
  return bytes;
}

void GpuBlockers::bind(const ComputeProgram& p) const {
  spheres_tex_.bind_sampler(bindings_.spheres);
  sky_bins_tex_.bind_sampler(bindings_.sky_bins);
  sun_bins_tex_.bind_sampler(bindings_.sun_bins);
  cap_log_tex_.bind_sampler(bindings_.cap_log);
  groups_tex_.bind_sampler(bindings_.groups);
  order_tex_.bind_sampler(bindings_.order);
  if (p.has_uniform("bin_tiles_x")) p.set_uniform("bin_tiles_x", tiles_x_);
  if (p.has_uniform("bin_tiles")) p.set_uniform("bin_tiles", tiles_);
  if (p.has_uniform("cull_budget")) p.set_uniform("cull_budget", static_cast<float>(cull_budget_));
  if (p.has_uniform("frame_groups")) p.set_uniform("frame_groups", group_count_);
  if (p.has_uniform("ratio_attenuation")) p.set_uniform("ratio_attenuation", ratio_attenuation_ ? 1.0f : 0.0f);
}

}  // namespace skylit::gpu
