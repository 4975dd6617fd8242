#include "gpu/field_limits.h"

#include "gpu/buffers.h"
#include <epoxy/gl.h>
#include "shading/horizon/horizon_march.h"
#include "terrain/pyramid.h"

#include <algorithm>
#include <cstdint>
#include <numeric>

namespace skylit::gpu {
namespace {

struct Limits {
  std::size_t storage_block_bytes = 0, texture_buffer_texels = 0, texture_size = 0;
};

Limits query_limits() {
  Limits l;
  GLint64 block = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &block);
  GLint texels = 0, size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &texels);
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &size);
  l.storage_block_bytes = static_cast<std::size_t>(block);
  l.texture_buffer_texels = static_cast<std::size_t>(texels);
  l.texture_size = static_cast<std::size_t>(size);
  return l;
}

bool fits(const Limits& l, int width, int height, shading::Product product, const shading::ProductOptions& o) {
  const std::size_t texels = static_cast<std::size_t>(width) * height;
  // The heights, pyramid level 0 and a lit product's sun shadow: 4 B a texel each.
  if (texels * sizeof(float) > l.storage_block_bytes) return false;
  if (o.march.use_pyramid) {
    const terrain::PyramidOptions po = horizon::march_pyramid_options(o.march);
    const int levels = terrain::pyramid_level_count(width, height, po);
    const std::size_t align = std::lcm(storage_offset_alignment(), sizeof(float)) / sizeof(float);
    std::size_t total = 0, scratch = 1;
    for (int k = 0; k < levels; ++k) {
      const terrain::LevelShape s = terrain::pyramid_level_shape(width, height, po.k_v, k);
      total = (total + align - 1) / align * align + static_cast<std::size_t>(s.width) * s.height;
      if (k > 0) scratch = std::max(scratch, static_cast<std::size_t>(height) * s.width);
    }
    if (total > l.texture_buffer_texels || scratch * sizeof(float) > l.storage_block_bytes) return false;
  }
  const bool sweeps = o.march.method == horizon::HorizonMethod::Sweep;  // bounded or not: the kernel's lines
  if (sweeps && !shading::traits(product).local &&
      static_cast<std::size_t>(2 * std::max(width, height) - 1) > l.texture_size)
    return false;
  return true;
}

}  // namespace

bool field_fits_gpu(int width, int height, shading::Product product, const shading::ProductOptions& options) {
  return fits(query_limits(), width, height, product, options);
}

}  // namespace skylit::gpu
