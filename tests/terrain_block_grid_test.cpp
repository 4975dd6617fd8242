// terrain/block_grid.h: the cores partition the raster, the reads are the cores grown by
// the halo and clipped.
#include "terrain/block_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace {

using skylit::terrain::block_grid;

TEST(BlockGrid, CoresCoverEveryTexelOnceAndReadsHoldTheHalo) {
  for (const auto& [w, h, n, halo] : std::vector<std::array<int, 4>>{{100, 70, 32, 5}, {64, 64, 64, 0}, {7, 300, 3, 40}, {1, 1, 8, 2}}) {
    const auto blocks = block_grid(w, h, n, halo);
    std::vector<int> hits(static_cast<std::size_t>(w) * h, 0);
    for (const auto& b : blocks) {
      EXPECT_LE(b.core.width, n);
      EXPECT_LE(b.core.height, n);
      for (int j = b.core.y0; j < b.core.y1(); ++j)
        for (int i = b.core.x0; i < b.core.x1(); ++i) ++hits[static_cast<std::size_t>(j) * w + i];
      EXPECT_EQ(b.read.x0, std::max(0, b.core.x0 - halo));
      EXPECT_EQ(b.read.y0, std::max(0, b.core.y0 - halo));
      EXPECT_EQ(b.read.x1(), std::min(w, b.core.x1() + halo));
      EXPECT_EQ(b.read.y1(), std::min(h, b.core.y1() + halo));
    }
    EXPECT_TRUE(std::all_of(hits.begin(), hits.end(), [](int c) { return c == 1; })) << w << "x" << h << " n " << n;
    EXPECT_EQ(blocks.size(), static_cast<std::size_t>(((w + n - 1) / n) * ((h + n - 1) / n)));
  }
}

TEST(BlockGrid, RowMajorFromTheOrigin) {
  const auto blocks = block_grid(10, 10, 4, 1);
  ASSERT_EQ(blocks.size(), 9u);
  EXPECT_EQ(blocks[1].core.x0, 4);
  EXPECT_EQ(blocks[1].core.y0, 0);
  EXPECT_EQ(blocks[3].core.y0, 4);
  EXPECT_EQ(blocks[8].core.width, 2);
}

TEST(BlockGrid, BadSizesThrow) {
  EXPECT_THROW(block_grid(0, 5, 4, 1), std::invalid_argument);
  EXPECT_THROW(block_grid(5, 5, 0, 1), std::invalid_argument);
  EXPECT_THROW(block_grid(5, 5, 4, -1), std::invalid_argument);
}

}  // namespace
