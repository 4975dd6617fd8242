// Whether a field fits one GPU frame, by the driver's limits that the pipeline checks
// when it builds (each storage block ≤ GL_MAX_SHADER_STORAGE_BLOCK_SIZE, the height
// pyramid ≤ GL_MAX_TEXTURE_BUFFER_SIZE texels, a sweep line ≤ GL_MAX_TEXTURE_SIZE
// samples). Front ends that process large DEMs in blocks size the blocks by it, so `auto`
// keeps them on the GPU rather than computing the whole DEM on the CPU. Needs a current
// OpenGL context.
#pragma once

#include "shading/products.h"

namespace skylit::gpu {

// For `product` with these options (a sweep is assumed wherever the options ask for one
// and the distance is unbounded).
bool field_fits_gpu(int width, int height, shading::Product product, const shading::ProductOptions& options);

}  // namespace skylit::gpu
