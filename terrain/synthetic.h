// Seeded, deterministic synthetic terrain: fBm of gradient (Perlin) noise for rolling
// relief, ridged multifractal noise for sharp crests, and a winding river valley carved
// across the scene. Same options (seed included) → the same heights, run after run
// (integer hashing, no std:: random distributions; only libm rounding may differ
// between platforms).
#pragma once

#include <cstdint>

#include "terrain/height_field.h"

namespace skylit::terrain {

struct SyntheticOptions {
  int width = 512;
  int height = 512;
  double spacing = 30.0;            // metres, square pixels
  std::uint64_t seed = 1;
  double base_height = 400.0;       // metres: the lowest height is exactly this
  double relief = 1800.0;           // metres: the highest is exactly base_height + relief
  double feature_size = 4000.0;     // metres, wavelength of the largest mountains
  int octaves = 6;                  // fBm / ridged octaves (finest ≈ feature_size / 2^(octaves−1))
  double ridge_weight = 0.55;       // 0 = rounded hills only, 1 = ridges only
  bool carve_valley = true;         // a winding river valley, west to east
  double valley_width = 900.0;      // metres, half-width of the valley floor influence
  double valley_depth = 0.85;       // 0…1: how far the valley axis is pulled down to the floor
};

// Throws std::invalid_argument on nonsensical options (sizes < 2, spacing ≤ 0, …).
HeightField make_synthetic_terrain(const SyntheticOptions& options = {});

// The application's built-in scene: 512 × 512 at 30 m, seed 1.
HeightField default_scene();

}  // namespace skylit::terrain
