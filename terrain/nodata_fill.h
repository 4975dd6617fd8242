// Filling nodata voids so the horizon marcher sees a continuous surface. The valid
// mask is left unchanged: filled texels stay valid = 0 and outputs write nodata there.
#pragma once

#include <cstdint>
#include <span>

namespace skylit::terrain {

// Laplace (membrane) inpainting: voids get the harmonic interpolation of the surrounding
// valid heights (∇²z = 0 inside voids, valid texels fixed; at the grid edge the
// gradient across the edge is zero). Solved coarse-to-fine: a push–pull mean pyramid
// gives the start, Gauss–Seidel sweeps on each finer level converge it.
// `valid` must have at least one nonzero entry.
void fill_laplace(std::span<float> heights, std::span<const std::uint8_t> valid, int width,
                  int height);

// Each void takes the height of a nearest valid texel (8-neighbour BFS distance).
void fill_nearest(std::span<float> heights, std::span<const std::uint8_t> valid, int width,
                  int height);

// Each void takes `value`.
void fill_constant(std::span<float> heights, std::span<const std::uint8_t> valid, float value);

}  // namespace skylit::terrain
