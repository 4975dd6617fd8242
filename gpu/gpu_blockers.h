// Sphere blockers on the GPU (shaders/sphere_blockers.glsl, blocker_sun.comp): the
// defines the kernels bake in, and per frame the spheres and their bins as buffer
// textures. The bins are the reference's (shading::frame_bins), so a texel tests the
// same spheres on both backends; they are made on the host, which takes microseconds
// for an aircraft (a sphere adds itself to the tiles its reach covers).
#pragma once

#include "gpu/buffers.h"
#include "gpu/compute_program.h"
#include "gpu/shader_source.h"
#include "shading/products.h"
#include "terrain/height_field.h"

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace skylit::gpu {

// Texture units of the buffer textures.
struct BlockerBindings {
  int spheres = 0, sky_bins = 0, sun_bins = 0, cap_log = 0, groups = 0, order = 0;
};

// Why the GPU cannot shade sphere blockers in `product` with these options (it runs the
// reference's defaults: log* caps, the product composition, the PS2 HYB), or nothing.
std::optional<std::string> gpu_lacks_blockers(shading::Product product, const shading::ProductOptions& options);

// The defines of sphere_blockers.glsl (BLOCKERS is the caller's): its sun part, and with `sky` its sky part
// (CAP_LOG_*, SH_ORDER is the caller's).
void add_blocker_defines(const shading::ProductOptions& options, const BlockerBindings& bindings, bool sky,
                         GlslDefines& defines);

class GpuBlockers {
 public:
  // `sky`: also the log* table of the caps (cap_log_table.h) at the options' SH order.
  GpuBlockers(const shading::ProductOptions& options, const BlockerBindings& bindings, bool sky);

  // A frame's spheres (field frame, shading::FrameInputs) and their bins for this
  // field and these options (the sun's bins from the options' lighting). Returns the
  // bytes uploaded.
  std::size_t upload(const terrain::HeightField& field, std::span<const blockers::Sphere> spheres,
                     const shading::ProductOptions& options);
  // Binds the buffers and sets a kernel's uniforms of sphere_blockers.glsl.
  void bind(const ComputeProgram& program) const;
  // The texels whose sky bins list a sphere after the last upload(): runs of such tiles
  // along each row of tiles, clipped to the field (the only texels the spheres' sky
  // change reaches).
  const std::vector<terrain::PixelRect>& sky_rects() const { return sky_rects_; }
  // Likewise the texels whose sun bins list a sphere (blocker_sun.comp's).
  const std::vector<terrain::PixelRect>& sun_rects() const { return sun_rects_; }

 private:
  BlockerBindings bindings_;
  Buffer spheres_, sky_bins_, sun_bins_, cap_log_, groups_, order_;
  BufferTexture spheres_tex_, sky_bins_tex_, sun_bins_tex_, cap_log_tex_, groups_tex_, order_tex_;
  int tiles_x_ = 0, tiles_ = 0;
  std::vector<terrain::PixelRect> sky_rects_, sun_rects_;
  double cull_budget_ = 0.0;
  int group_count_ = 0;
  bool ratio_attenuation_ = false;
};

}  // namespace skylit::gpu
