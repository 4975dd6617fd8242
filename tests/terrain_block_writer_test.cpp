// terrain/block_raster_writer.h: blocks written in any order read back as one raster, in
// formats GDAL creates (GTiff) and copy-only ones (COG, with overviews; PNG); nothing is
// left behind without finish(), and targets are checked as write_raster checks them.
#include "terrain/block_raster_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

#include "terrain/block_grid.h"
#include "terrain_test_util.h"

namespace {

using skylit::terrain::BlockRasterWriter;
using skylit::terrain::GeoReference;
using skylit::terrain::PixelRect;
using skylit::terrain::RasterWriteError;
using skylit::terrain::RasterWriteOptions;
using skylit::terrain::testing::ScratchDir;

GeoReference utm() { return skylit::terrain::testing::utm_georef(); }

// Value of band b at (i, j): distinct everywhere, so a misplaced block shows.
float value(int b, int i, int j) { return static_cast<float>(b * 1e6 + j * 1000 + i); }

// Writes a w × h, `bands`-band raster as blocks of n in a shuffled order.
void write_blocks(BlockRasterWriter& writer, int w, int h, int bands, int n) {
  auto blocks = skylit::terrain::block_grid(w, h, n, 0);
  std::shuffle(blocks.begin(), blocks.end(), std::mt19937(7));
  for (const auto& blk : blocks) {
    std::vector<float> v;
    for (int b = 0; b < bands; ++b)
      for (int j = blk.core.y0; j < blk.core.y1(); ++j)
        for (int i = blk.core.x0; i < blk.core.x1(); ++i) v.push_back(value(b, i, j));
    writer.write(blk.core, std::span<const float>(v));
  }
}

void expect_raster(const std::string& path, int w, int h, int bands) {
  skylit::terrain::testing::ensure_gdal();
  GDALDataset* ds = GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY);
  ASSERT_NE(ds, nullptr) << path;
  ASSERT_EQ(ds->GetRasterXSize(), w);
  ASSERT_EQ(ds->GetRasterCount(), bands);
  double gt[6];
  ds->GetGeoTransform(gt);
  EXPECT_EQ(gt[0], 500000);
  EXPECT_EQ(gt[5], -30);
  std::vector<float> v(static_cast<std::size_t>(w) * h);
  for (int b = 0; b < bands; ++b) {
    ASSERT_EQ(ds->GetRasterBand(b + 1)->RasterIO(GF_Read, 0, 0, w, h, v.data(), w, h, GDT_Float32, 0, 0, nullptr), CE_None);
    int bad = 0;
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) bad += v[static_cast<std::size_t>(j) * w + i] != value(b, i, j);
    EXPECT_EQ(bad, 0) << "band " << b;
  }
  GDALClose(GDALDataset::ToHandle(ds));
}

TEST(BlockRasterWriter, GeoTiffFromShuffledBlocks) {
  ScratchDir dir;
  RasterWriteOptions o;
  o.band_descriptions = {"a", "b"};
  BlockRasterWriter writer(dir.file("out.tif"), utm(), 301, 173, 2, BlockRasterWriter::Sample::Float32, o);
  write_blocks(writer, 301, 173, 2, 64);
  EXPECT_EQ(dir.listing().size(), 1u);  // the staging folder only
  writer.finish();
  EXPECT_EQ(dir.listing(), std::vector<std::string>{"out.tif"});
  expect_raster(dir.file("out.tif"), 301, 173, 2);
}

TEST(BlockRasterWriter, CogGetsItsOverviewsAtFinish) {
  ScratchDir dir;
  RasterWriteOptions o;
  o.format = "COG";
  o.creation_options = {"BLOCKSIZE=256"};
  int calls = 0;
  o.progress = [&](double) { return ++calls > 0; };
  BlockRasterWriter writer(dir.file("out.tif"), utm(), 1100, 700, 1, BlockRasterWriter::Sample::Float32, o);
  write_blocks(writer, 1100, 700, 1, 300);
  EXPECT_EQ(calls, 0);
  writer.finish();
  EXPECT_GT(calls, 0);
  EXPECT_EQ(dir.listing(), std::vector<std::string>{"out.tif"});
  expect_raster(dir.file("out.tif"), 1100, 700, 1);
  GDALDataset* ds = GDALDataset::Open(dir.file("out.tif").c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY);
  ASSERT_NE(ds, nullptr);
  const char* layout = ds->GetMetadataItem("LAYOUT", "IMAGE_STRUCTURE");
  EXPECT_STREQ(layout ? layout : "", "COG");
  // Halvings until the longer side fits one 256-texel block: 550, 275, 138.
  EXPECT_EQ(ds->GetRasterBand(1)->GetOverviewCount(), 3);
  GDALClose(GDALDataset::ToHandle(ds));
}

TEST(BlockRasterWriter, EightBitPng) {
  ScratchDir dir;
  RasterWriteOptions o;
  o.format = "PNG";
  BlockRasterWriter writer(dir.file("out.png"), utm(), 90, 50, 1, BlockRasterWriter::Sample::Byte, o);
  for (const auto& blk : skylit::terrain::block_grid(90, 50, 32, 0)) {
    std::vector<std::uint8_t> v;
    for (int j = blk.core.y0; j < blk.core.y1(); ++j)
      for (int i = blk.core.x0; i < blk.core.x1(); ++i) v.push_back(static_cast<std::uint8_t>((i + 3 * j) % 256));
    writer.write(blk.core, std::span<const std::uint8_t>(v));
  }
  writer.finish();
  GDALDataset* ds = GDALDataset::Open(dir.file("out.png").c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY);
  ASSERT_NE(ds, nullptr);
  std::vector<std::uint8_t> v(90 * 50);
  ASSERT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, 90, 50, v.data(), 90, 50, GDT_Byte, 0, 0, nullptr), CE_None);
  int bad = 0;
  for (int j = 0; j < 50; ++j)
    for (int i = 0; i < 90; ++i) bad += v[j * 90 + i] != (i + 3 * j) % 256;
  EXPECT_EQ(bad, 0);
  GDALClose(GDALDataset::ToHandle(ds));
}

TEST(BlockRasterWriter, UnfinishedLeavesNothingAndKeepsTheOldFile) {
  ScratchDir dir;
  const std::string path = dir.file("out.tif");
  {
    BlockRasterWriter first(path, utm(), 50, 50, 1, BlockRasterWriter::Sample::Float32);
    write_blocks(first, 50, 50, 1, 50);
    first.finish();
  }
  const auto size = std::filesystem::file_size(path);
  {
    RasterWriteOptions o;
    o.format = "COG";
    BlockRasterWriter second(path, utm(), 80, 80, 1, BlockRasterWriter::Sample::Float32, o);
    write_blocks(second, 80, 40, 1, 20);  // abandoned
  }
  EXPECT_EQ(dir.listing(), std::vector<std::string>{"out.tif"});
  EXPECT_EQ(std::filesystem::file_size(path), size);
  expect_raster(path, 50, 50, 1);
}

TEST(BlockRasterWriter, BadTargetsAndBlocksThrow) {
  ScratchDir dir;
  RasterWriteOptions keep;
  keep.overwrite = false;
  const std::string path = dir.file("out.tif");
  { BlockRasterWriter w(path, utm(), 8, 8, 1, BlockRasterWriter::Sample::Float32); write_blocks(w, 8, 8, 1, 8); w.finish(); }
  EXPECT_THROW(BlockRasterWriter(path, utm(), 8, 8, 1, BlockRasterWriter::Sample::Float32, keep), RasterWriteError);
  EXPECT_THROW(BlockRasterWriter(dir.file("no/such/out.tif"), utm(), 8, 8, 1, BlockRasterWriter::Sample::Float32),
               RasterWriteError);
  RasterWriteOptions png;
  png.format = "PNG";
  EXPECT_THROW(BlockRasterWriter(dir.file("f.png"), utm(), 8, 8, 1, BlockRasterWriter::Sample::Float32, png),
               RasterWriteError);  // PNG holds no Float32
  BlockRasterWriter w(dir.file("b.tif"), utm(), 8, 8, 1, BlockRasterWriter::Sample::Float32);
  const std::vector<float> four(4, 1.0f);
  EXPECT_THROW(w.write(PixelRect{7, 7, 2, 2}, std::span<const float>(four)), RasterWriteError);  // outside
  EXPECT_THROW(w.write(PixelRect{0, 0, 3, 3}, std::span<const float>(four)), RasterWriteError);  // count
  const std::vector<std::uint8_t> bytes(4, 1);
  EXPECT_THROW(w.write(PixelRect{0, 0, 2, 2}, std::span<const std::uint8_t>(bytes)), RasterWriteError);  // type
}

}  // namespace
