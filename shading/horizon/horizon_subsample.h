// The coarse grid of horizon sub-sampling (ProductOptions::subsample, products.h) along
// one axis of `size` texels with step s: coarse positions 0, s, 2s, … and always the
// last index size − 1. Shared by the CPU reference (reference_renderer.cpp) and the GPU
// host (gpu_pipeline.cpp); shaders/subsample.glsl restates position() and bracket() in GLSL.
#pragma once

#include "terrain/height_field.h"

#include <algorithm>

namespace skylit::horizon {

struct SubsampleAxis {
  int size = 1;  // texels along the axis
  int step = 1;  // s

  // Coarse positions: ⌊(size−1)/s⌋ + 1, plus the last index when s does not divide size − 1.
  int count() const { return (size - 1) / step + 1 + ((size - 1) % step != 0 ? 1 : 0); }
  // Texel index of coarse position c.
  int position(int c) const { return std::min(c * step, size - 1); }
  // Whether texel t is a coarse position.
  bool coarse(int t) const { return t % step == 0 || t == size - 1; }

  // Texel i lies between coarse positions c0 ≤ c1 with linear weight `a` on c1;
  // c0 == c1 (a = 0) when i is itself a coarse position.
  struct Bracket {
    int c0 = 0, c1 = 0;
    double a = 0.0;
  };
  Bracket bracket(int i) const {
    const int c0 = i / step;
    if (c0 * step == i) return {c0, c0, 0.0};
    const int p0 = c0 * step, p1 = position(c0 + 1);
    return {c0, c0 + 1, static_cast<double>(i - p0) / (p1 - p0)};
  }
};

// `region` (MarchOptions::region; empty: the whole field) grown by the coarse texels its
// texels' horizons are interpolated from, within the field.
terrain::PixelRect subsample_region(const terrain::HeightField& field, const terrain::PixelRect& region, int step);

}  // namespace skylit::horizon
