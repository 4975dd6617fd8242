#include "view/display_defines.h"

#include "shading/products.h"

namespace skylit::view {

gpu::GlslDefines display_code_defines() {
  gpu::GlslDefines d;
  d.set("SRGB_LINEAR_LIMIT", shading::kSrgbLinearLimit)
      .set("SRGB_LINEAR_SLOPE", shading::kSrgbLinearSlope)
      .set("SRGB_SCALE", shading::kSrgbScale)
      .set("SRGB_OFFSET", shading::kSrgbOffset)
      .set("SRGB_GAMMA", shading::kSrgbGamma)
      .set("FIRST_CODE", shading::kFirstCode)
      .set("CODE_SPAN", shading::kCodeSpan);
  return d;
}

}  // namespace skylit::view
