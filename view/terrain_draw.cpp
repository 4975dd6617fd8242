#include "view/terrain_draw.h"

#include <epoxy/gl.h>

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstddef>
#include <vector>

#include "gpu/gl_context.h"
#include "view/display_defines.h"

namespace skylit::view {
namespace {

gpu::GlslDefines terrain_defines(const terrain::HeightField& field) {
  gpu::GlslDefines d;
  d.set("PATCH", kPatchQuads).set("NODATA", field.any_nodata() ? 1 : 0);
  return d;
}

// The skirt ring's sides, in the order of patch_indices()'s strips.
enum Side { kNorth, kSouth, kWest, kEast, kSides };

// Two triangles per quad of the (PATCH + 2)² grid of the patch with its skirt ring,
// counter-clockwise seen from above (a runs east, b south): the ground faces up and
// each skirt faces out of its patch, so culling back faces keeps every skirt that
// hides a crack (the one hung from the higher edge faces the viewer on the lower side).
// First the PATCH² quads of ground, then one strip of PATCH quads per side (Side's
// order), each hung below that side's edge. The ring's corner quads are left out: all
// their ring vertices sit below the patch's corner, so both their triangles are empty.
std::vector<std::uint32_t> patch_indices() {
  const int n = kPatchQuads + 3;  // vertices per side
  std::vector<std::uint32_t> out;
  out.reserve(static_cast<std::size_t>(kPatchQuads) * (kPatchQuads + 4) * 6);
  auto quad = [&](int a, int b) {
    const std::uint32_t v = static_cast<std::uint32_t>(b * n + a);
    out.insert(out.end(), {v, v + n, v + 1, v + 1, v + n, v + n + 1});
  };
  for (int b = 1; b <= kPatchQuads; ++b)
    for (int a = 1; a <= kPatchQuads; ++a) quad(a, b);
  for (int a = 1; a <= kPatchQuads; ++a) quad(a, 0);               // north
  for (int a = 1; a <= kPatchQuads; ++a) quad(a, kPatchQuads + 1);  // south
  for (int b = 1; b <= kPatchQuads; ++b) quad(0, b);               // west
  for (int b = 1; b <= kPatchQuads; ++b) quad(kPatchQuads + 1, b);  // east
  return out;
}
constexpr int kGroundIndices = kPatchQuads * kPatchQuads * 6, kSideIndices = kPatchQuads * 6;
constexpr std::size_t kPatchesPerFlush = 128;

// One node as view_terrain.vert reads it: per-instance attributes 0 (ivec3) and 1 (float).
struct NodeRecord {
  std::int32_t i0, j0, stride;
  float skirt_m;
};

}  // namespace

TerrainDraw::TerrainDraw(const terrain::HeightField& field)
    : lod_(field),
      heights_(field.width, field.height, gpu::TextureFormat::R32F),
      colour_map_(field.width, field.height, gpu::TextureFormat::RGBA8),
      colour_kernel_(gpu::ComputeProgram::from_embedded("view_terrain_colour.comp", display_code_defines())),
      program_("view_terrain.vert", "view_terrain.frag", terrain_defines(field)),
      width_(field.width),
      height_(field.height),
      dx_(field.mean_dx()),
      dy_(field.dy) {
  heights_.upload(field.heights);
  colour_map_.set_linear_filter();
  revision_ = field.revision;
  field_id_ = field.id.value();
  const std::vector<std::uint32_t> idx = patch_indices();
  glCreateVertexArrays(1, &vao_);
  glCreateBuffers(1, &indices_);
  glNamedBufferStorage(indices_, static_cast<GLsizeiptr>(idx.size() * sizeof(std::uint32_t)), idx.data(), 0);
  glVertexArrayElementBuffer(vao_, indices_);
  glVertexArrayAttribIFormat(vao_, 0, 3, GL_INT, offsetof(NodeRecord, i0));
  glVertexArrayAttribFormat(vao_, 1, 1, GL_FLOAT, GL_FALSE, offsetof(NodeRecord, skirt_m));
  for (GLuint attribute : {0u, 1u}) {
    glVertexArrayAttribBinding(vao_, attribute, 0);
    glEnableVertexArrayAttrib(vao_, attribute);
  }
  glVertexArrayBindingDivisor(vao_, 0, 1);
  gpu::throw_on_gl_error("TerrainDraw");
}

TerrainDraw::~TerrainDraw() {
  glDeleteBuffers(1, &indices_);
  glDeleteVertexArrays(1, &vao_);
}

void TerrainDraw::sync(const terrain::HeightField& field) {
  if (field.id.value() != field_id_ || field.width != width_ || field.height != height_)
    throw std::logic_error("TerrainDraw::sync: another field (make a new TerrainDraw)");
  if (field.revision == revision_) return;
  const terrain::PixelRect r = field.last_dirty;
  if (!r.empty()) {
    glPixelStorei(GL_UNPACK_ROW_LENGTH, field.width);
    glTextureSubImage2D(heights_.id(), 0, r.x0, r.y0, r.width, r.height, GL_RED, GL_FLOAT,
                        field.heights.data() + static_cast<std::size_t>(r.y0) * field.width + r.x0);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    lod_.update(field, r);
  }
  revision_ = field.revision;
}

void TerrainDraw::set_colour(const gpu::GpuFrame& frame, shading::ToneCurve tone) {
  if (frame.width != width_ || frame.height != height_)
    throw std::invalid_argument("TerrainDraw: the frame is not of this field");
  const bool same_map = colour_scale_ == frame.display_scale && colour_bands_ == frame.band_count &&
                        colour_tone_ == tone;
  if (same_map && colour_serial_ == frame.serial) return;
  colour_kernel_.set_uniform("field_size", width_, height_);
  colour_kernel_.set_uniform("band_count", frame.band_count);
  colour_kernel_.set_uniform("display_scale", static_cast<float>(frame.display_scale));
  colour_kernel_.set_uniform("srgb", tone == shading::ToneCurve::Srgb ? 1 : 0);
  frame.bands.bind_storage(0);
  colour_map_.bind_image(0, false, true);
  auto colour = [&](const terrain::PixelRect& r) {
    colour_kernel_.set_uniform("origin", r.x0, r.y0);
    colour_kernel_.set_uniform("extent", r.width, r.height);
    colour_kernel_.dispatch_covering(r.width, r.height);
  };
  if (frame.changed && same_map && colour_serial_ + 1 == frame.serial) {
    for (const terrain::PixelRect& r : *frame.changed) {
      // A nodata texel takes a neighbour's colour: one texel around changes with it.
      const int x0 = std::max(0, r.x0 - 1), y0 = std::max(0, r.y0 - 1);
      const terrain::PixelRect grown{x0, y0, std::min(width_, r.x1() + 1) - x0, std::min(height_, r.y1() + 1) - y0};
      if (!r.empty() && !grown.empty()) colour(grown);
    }
  } else {
    colour({0, 0, width_, height_});
  }
  colour_scale_ = frame.display_scale;
  colour_bands_ = frame.band_count;
  colour_serial_ = frame.serial;
  colour_tone_ = tone;
}

void TerrainDraw::draw(const glm::dmat4& view_proj, const glm::dvec3& eye, double pixels_per_radian,
                       const TerrainStyle& style) {
  LodView v;
  v.view_proj = view_proj;
  v.eye = eye;
  v.pixels_per_radian = pixels_per_radian;
  v.max_error_px = style.max_error_px;
  v.exaggeration = style.exaggeration;
  const CurvatureDrop drop = curvature_drop(style.curvature, eye, pixels_per_radian);
  v.curvature = drop.per_m2;
  std::vector<LodNode> nodes = lod_.select(v);
  nodes_ = nodes.size();
  // Nearest first: hidden ground then fails the depth test before it is shaded.
  const auto distance2 = [&](const LodNode& n) {
    const double half = 0.5 * kPatchQuads * n.stride;
    const double x = (n.i0 + half) * dx_ - eye.x, y = -(n.j0 + half) * dy_ - eye.y;
    return x * x + y * y;
  };
  std::sort(nodes.begin(), nodes.end(), [&](const LodNode& a, const LodNode& b) { return distance2(a) < distance2(b); });

  // A side needs its skirt only where the patch meets one of another stride: next to
  // one of its own stride (aligned in the quadtree) the edges' vertices are the same.
  // Beyond the field's edge none hangs (view_terrain.vert).
  // Per level-0 node (TerrainLod's): the stride of the selected node over it, 0 if none.
  const glm::ivec2 cells = lod_.node_counts(0);
  const int cells_x = cells.x, cells_y = cells.y;
  std::vector<int> cell_stride(static_cast<std::size_t>(cells_x) * cells_y, 0);
  for (const LodNode& n : nodes)
    for (int r = n.j0 / kPatchQuads; r < std::min(cells_y, n.j0 / kPatchQuads + n.stride); ++r)
      for (int c = n.i0 / kPatchQuads; c < std::min(cells_x, n.i0 / kPatchQuads + n.stride); ++c)
        cell_stride[static_cast<std::size_t>(r) * cells_x + c] = n.stride;
  auto needs_skirt = [&](const LodNode& n, Side side) {
    const int c0 = n.i0 / kPatchQuads, r0 = n.j0 / kPatchQuads;
    const int c = side == kWest ? c0 - 1 : side == kEast ? c0 + n.stride : c0;
    const int r = side == kNorth ? r0 - 1 : side == kSouth ? r0 + n.stride : r0;
    if (c < 0 || r < 0 || c >= cells_x || r >= cells_y) return false;
    return cell_stride[static_cast<std::size_t>(r) * cells_x + c] != n.stride;
  };

  // The records: every node's, then each side's nodes that hang a skirt there.
  std::vector<NodeRecord> records;
  records.reserve(2 * nodes.size());
  for (const LodNode& n : nodes)
    // Deep enough to hide the step to a neighbour of another stride on steep ground.
    records.push_back({n.i0, n.j0, n.stride,
                       static_cast<float>(std::max(5.0, 2.0 * n.stride * std::max(dx_, dy_)) * style.exaggeration)});
  std::size_t side_first[kSides], side_count[kSides];
  for (int side = 0; side < kSides; ++side) {
    side_first[side] = records.size();
    for (std::size_t k = 0; k < nodes.size(); ++k)
      if (needs_skirt(nodes[k], static_cast<Side>(side))) records.push_back(records[k]);
    side_count[side] = records.size() - side_first[side];
  }
  skirts_ = records.size() - nodes.size();
  if (nodes.empty()) return;
  const std::size_t bytes = records.size() * sizeof(NodeRecord);
  if (node_buffer_.size_bytes() < bytes) node_buffer_ = gpu::Buffer(bytes);
  node_buffer_.upload(records.data(), bytes);

  const glm::mat4 vp(view_proj);
  program_.use();
  program_.set_mat4("view_proj", glm::value_ptr(vp));
  program_.set("field_size", width_, height_);
  program_.set("spacing", static_cast<float>(dx_), static_cast<float>(dy_));
  program_.set("exaggeration", static_cast<float>(style.exaggeration));
  set_curvature_uniforms(program_, drop);
  heights_.bind_sampler(0);
  colour_map_.bind_sampler(1);
  glVertexArrayVertexBuffer(vao_, 0, node_buffer_.id(), 0, sizeof(NodeRecord));
  // Few draws for all the ground and one per side's skirts (llvmpipe pays per draw call
  // and per triangle); instances are drawn in order.
  // Back faces (slopes facing away, skirts seen from inside their patch) are hidden from
  // any eye above the terrain; culling them spares llvmpipe their binning.
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glBindVertexArray(vao_);
  auto draw_range = [&](std::size_t first_index, int count, std::size_t first_node, std::size_t instances) {
    if (instances == 0) return;
    glDrawElementsInstancedBaseInstance(GL_TRIANGLES, count, GL_UNSIGNED_INT,
                                        reinterpret_cast<const void*>(first_index * sizeof(std::uint32_t)),
                                        static_cast<GLsizei>(instances), static_cast<GLuint>(first_node));
  };
  // The ground in runs of kPatchesPerFlush, flushed after each: llvmpipe bins a draw on
  // this thread and rasterizes only what is flushed, so its raster threads shade the nearer
  // patches while this thread bins the farther ones (terrain pass 0.85-0.9x on 2 cores).
  for (std::size_t first = 0; first < nodes.size(); first += kPatchesPerFlush) {
    draw_range(0, kGroundIndices, first, std::min(kPatchesPerFlush, nodes.size() - first));
    if (first + kPatchesPerFlush < nodes.size()) glFlush();
  }
  for (int side = 0; side < kSides; ++side)
    draw_range(kGroundIndices + static_cast<std::size_t>(side) * kSideIndices, kSideIndices, side_first[side],
               side_count[side]);
  glBindVertexArray(0);
  glDisable(GL_CULL_FACE);
  gpu::throw_on_gl_error("TerrainDraw::draw");
}

}  // namespace skylit::view
