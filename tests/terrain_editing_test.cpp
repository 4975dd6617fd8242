// Edits and moving windows: bounds checks, revision/dirty tracking, georeference.
#include <gtest/gtest.h>

#include <cmath>

#include "terrain/editing.h"

namespace skylit::terrain {
namespace {

HeightField numbered(int w, int h) {
  HeightField f(w, h, 10.0);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) f.at(i, j) = static_cast<float>(100 * j + i);
  for (int j = 0; j < h; ++j) f.dx_per_row[j] = 5.0 + j;
  f.georef.geotransform = {1000, 10, 0, 2000, 0, -10};
  f.nodata = -1;
  return f;
}

// Identity for GPU residency: never shared by two live fields, kept across a move.
TEST(TerrainEditing, FieldIdsAreUniqueCopiesAreNewMovesKeepTheirs) {
  HeightField a(4, 3, 10.0), b(4, 3, 10.0);
  EXPECT_NE(a.id.value(), b.id.value());
  const HeightField copy = a;
  EXPECT_NE(copy.id.value(), a.id.value());
  const std::uint64_t a_id = a.id.value();
  HeightField moved = std::move(a);
  EXPECT_EQ(moved.id.value(), a_id);
  EXPECT_NE(a.id.value(), a_id);  // the moved-from object is another field now
  b = moved;                      // b now holds moved's data but stays its own object
  EXPECT_NE(b.id.value(), moved.id.value());
  b = std::move(moved);
  EXPECT_EQ(b.id.value(), a_id);
  EXPECT_NE(moved.id.value(), a_id);
}

TEST(TerrainEditing, ReplaceHeightsTracksRevision) {
  HeightField f = numbered(8, 6);
  f.valid[2 * 8 + 3] = 0;
  const auto rev = f.revision;
  replace_heights(f, {2, 1, 3, 2}, std::vector<float>{1, 2, 3, 4, 5, 6});
  EXPECT_EQ(f.revision, rev + 1);
  EXPECT_EQ(f.last_dirty, (PixelRect{2, 1, 3, 2}));
  EXPECT_EQ(f.at(2, 1), 1);
  EXPECT_EQ(f.at(4, 2), 6);
  EXPECT_TRUE(f.is_valid(3, 2));  // replaced texels are measured heights now
  EXPECT_EQ(f.at(5, 1), 105);     // untouched
}

// What an incremental copy of the field may rely on: one change since its revision, and a
// rectangle inside the grid.
TEST(TerrainEditing, OneEditSinceIsOneMarkOfANonEmptyRectangle) {
  HeightField f = numbered(8, 6);
  const auto rev = f.revision;
  EXPECT_FALSE(f.one_edit_since(rev));  // nothing since
  f.mark_dirty({2, 1, 3, 2});
  EXPECT_TRUE(f.one_edit_since(rev));
  EXPECT_FALSE(f.one_edit_since(rev + 1));
  f.mark_dirty({6, 4, 5, 5});  // clipped to the grid: still one edit since the last
  EXPECT_TRUE(f.one_edit_since(rev + 1));
  EXPECT_FALSE(f.one_edit_since(rev));  // two since the first
  f.mark_dirty({20, 20, 2, 2});  // wholly outside: an empty rectangle says nothing
  EXPECT_FALSE(f.one_edit_since(rev + 2));
}

TEST(TerrainEditing, ReplaceHeightsValidates) {
  HeightField f = numbered(8, 6);
  const auto rev = f.revision;
  EXPECT_THROW(replace_heights(f, {7, 0, 2, 1}, std::vector<float>{1, 2}), EditError);  // off the east edge
  EXPECT_THROW(replace_heights(f, {-1, 0, 1, 1}, std::vector<float>{1}), EditError);
  EXPECT_THROW(replace_heights(f, {0, 0, 0, 1}, std::vector<float>{}), EditError);      // empty
  EXPECT_THROW(replace_heights(f, {0, 0, 2, 2}, std::vector<float>{1, 2, 3}), EditError);  // size
  EXPECT_THROW(replace_heights(f, {0, 0, 1, 1}, std::vector<float>{NAN}), EditError);
  EXPECT_EQ(f.revision, rev);  // nothing changed
  EXPECT_EQ(f.at(0, 0), 0);
}

TEST(TerrainEditing, ExtractWindowKeepsGeoreference) {
  const HeightField f = numbered(8, 6);
  const HeightField w = extract_window(f, {3, 2, 4, 3});
  EXPECT_EQ(w.width, 4);
  EXPECT_EQ(w.height, 3);
  EXPECT_EQ(w.at(0, 0), 203);
  EXPECT_EQ(w.at(3, 2), 406);
  EXPECT_DOUBLE_EQ(w.georef.geotransform[0], 1030);
  EXPECT_DOUBLE_EQ(w.georef.geotransform[3], 1980);
  ASSERT_EQ(w.dx_per_row.size(), 3u);
  EXPECT_DOUBLE_EQ(w.dx(0), 7.0);  // source row 2
  EXPECT_EQ(w.nodata, -1);
  EXPECT_THROW(extract_window(f, {6, 0, 4, 2}), EditError);
}

TEST(TerrainEditing, MosaicWindowMoves) {
  const HeightField f = numbered(20, 12);
  MosaicWindow win(f, 5, 4);
  EXPECT_EQ(win.field().at(0, 0), 0);
  const auto rev = win.field().revision;
  win.move_to(10, 6);
  EXPECT_EQ(win.field().revision, rev + 1);
  EXPECT_EQ(win.field().last_dirty, win.field().bounds());
  EXPECT_EQ(win.field().at(0, 0), 610);
  EXPECT_EQ(win.field().at(4, 3), 914);
  EXPECT_DOUBLE_EQ(win.field().georef.geotransform[0], 1100);
  EXPECT_DOUBLE_EQ(win.field().dx(0), 11.0);
  win.move_to(10, 6);  // no move, no revision
  EXPECT_EQ(win.field().revision, rev + 1);
  EXPECT_THROW(win.move_to(16, 0), EditError);
  EXPECT_EQ(win.rect(), (PixelRect{10, 6, 5, 4}));  // unchanged after the failed move
  win.center_on(0, 100);                            // clamped to the south-west corner
  EXPECT_EQ(win.rect(), (PixelRect{0, 8, 5, 4}));
  EXPECT_THROW(MosaicWindow(f, 30, 4), EditError);
}

TEST(TerrainEditing, DirtyRectClipsAndUnions) {
  HeightField f(10, 10, 1.0);
  f.mark_dirty({8, 8, 5, 5});
  EXPECT_EQ(f.last_dirty, (PixelRect{8, 8, 2, 2}));
  EXPECT_EQ(bounding_union({0, 0, 2, 2}, {5, 6, 1, 1}), (PixelRect{0, 0, 6, 7}));
  EXPECT_EQ(bounding_union({}, {5, 6, 1, 1}), (PixelRect{5, 6, 1, 1}));
}

}  // namespace
}  // namespace skylit::terrain
