// The #defines of shaders/display_code.glsl, generated from shading/products.h's
// constants (the tone curve is written once, in C++).
#pragma once

#include "gpu/shader_source.h"

namespace skylit::view {

gpu::GlslDefines display_code_defines();

}  // namespace skylit::view
