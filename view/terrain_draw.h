// Draws the height field as a mesh (terrain_lod.h's nodes, one instanced patch each)
// coloured by a `shaded` frame that stays on the GPU (gpu::GpuFrame). Needs a current
// GL 4.5 context, the one the frame was computed in.
#pragma once

#include <glm/mat4x4.hpp>

#include <cstdint>

#include "gpu/buffers.h"
#include "gpu/compute_program.h"
#include "gpu/gpu_renderer.h"
#include "gpu/graphics_program.h"
#include "shading/products.h"
#include "terrain/height_field.h"
#include "view/curvature_drop.h"
#include "view/terrain_lod.h"

namespace skylit::view {

struct TerrainStyle {
  double exaggeration = 1.0;
  bool curvature = true;
  double max_error_px = kDefaultMeshErrorPx;  // the mesh's geometric error on screen (TerrainLod)
  shading::ToneCurve tone = shading::ToneCurve::Srgb;  // of the colour map (TerrainDraw::set_colour)
};

class TerrainDraw {
 public:
  explicit TerrainDraw(const terrain::HeightField& field);
  ~TerrainDraw();
  TerrainDraw(const TerrainDraw&) = delete;
  TerrainDraw& operator=(const TerrainDraw&) = delete;

  // Re-uploads the rows the field's last edit changed (a no-op when the field's revision
  // is the one drawn).
  void sync(const terrain::HeightField& field);
  // The colour of the draws that follow: the frame's 8-bit display codes under `tone`, one
  // RGBA8 texel per field texel, filtered by the fragments in one lookup (on llvmpipe an
  // 8-bit bilinear lookup costs a fraction of a float one, and the tone curve's pow runs
  // once a texel instead of once a fragment). A no-op for the frame and tone it holds: the
  // tiles of a screenshot redraw the same colour. A frame that says which texels changed
  // (GpuFrame::changed) under the same display scale and tone recolours only those.
  void set_colour(const gpu::GpuFrame& frame, shading::ToneCurve tone);
  // pixels_per_radian 0: orthographic (every node at full resolution). Needs set_colour().
  void draw(const glm::dmat4& view_proj, const glm::dvec3& eye, double pixels_per_radian, const TerrainStyle& style);
  std::size_t last_node_count() const { return nodes_; }
  // The skirts it hung (a patch's side each): only where patches of different strides meet.
  std::size_t last_skirt_count() const { return skirts_; }

 private:

  TerrainLod lod_;
  gpu::Texture2D heights_;
  gpu::Texture2D colour_map_;
  gpu::ComputeProgram colour_kernel_;
  gpu::GraphicsProgram program_;
  gpu::Buffer node_buffer_;  // NodeRecord per drawn node
  std::uint32_t vao_ = 0, indices_ = 0;
  int width_, height_;
  double dx_, dy_;
  std::uint64_t revision_ = 0, field_id_ = 0;
  std::size_t nodes_ = 0, skirts_ = 0;
  double colour_scale_ = -1.0;  // what the colour map holds: the frame's display scale, bands, serial
  int colour_bands_ = 0;
  std::uint64_t colour_serial_ = 0;
  shading::ToneCurve colour_tone_ = shading::ToneCurve::Srgb;
};

}  // namespace skylit::view
