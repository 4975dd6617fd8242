// A DEM read in strips (read_dem_in_strips) and staged for the warper (StagedDem): the
// strips put together equal read_dem of the whole file (north-up, south-up, mosaics with
// gaps, stray NaN), the copy on disk equals the copy in memory bit for bit, and no
// temporary file outlives the read, also when it fails half-way.
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "terrain/dem_reader.h"
#include "terrain/staged_dem.h"
#include "terrain_test_util.h"

namespace skylit::terrain {
namespace {

using testing::make_raster;
using testing::ramp;
using testing::RasterSpec;
using testing::ScratchDir;

// The strips' pixels placed by their first rows; `rows_seen` counts each row's strips.
struct Assembled {
  DemReadResult result;
  std::vector<float> heights;
  std::vector<std::uint8_t> valid;
  std::vector<int> rows_seen;
};

Assembled assemble(const std::vector<std::string>& paths, int rows) {
  const DemInfo info = inspect_dem(paths);
  Assembled a;
  const std::size_t n = static_cast<std::size_t>(info.width) * info.height;
  a.heights.assign(n, -1.0f);
  a.valid.assign(n, 2);
  a.rows_seen.assign(info.height, 0);
  a.result = read_dem_in_strips(paths, {}, rows, [&](const HeightField& strip, int first_row) {
    EXPECT_EQ(strip.width, info.width);
    EXPECT_GE(strip.height, 2);
    for (int j = 0; j < strip.height; ++j) {
      ++a.rows_seen.at(first_row + j);
      for (int i = 0; i < strip.width; ++i) {
        const std::size_t k = static_cast<std::size_t>(first_row + j) * info.width + i;
        a.heights[k] = strip.at(i, j);
        a.valid[k] = strip.valid[static_cast<std::size_t>(j) * strip.width + i];
      }
    }
  });
  return a;
}

void expect_equals_whole_read(const std::vector<std::string>& paths, int rows) {
  SCOPED_TRACE("strips of " + std::to_string(rows) + " rows");
  const DemReadResult whole = read_dem(paths);
  const Assembled a = assemble(paths, rows);
  for (int j = 0; j < whole.field.height; ++j) ASSERT_EQ(a.rows_seen[j], 1) << "row " << j;
  for (std::size_t k = 0; k < whole.field.size(); ++k) {
    ASSERT_EQ(a.valid[k], whole.field.valid[k]) << "pixel " << k;
    if (a.valid[k]) {
      ASSERT_EQ(a.heights[k], whole.field.heights[k]) << "pixel " << k;
    }
  }
  const HeightField& o = a.result.field;
  EXPECT_TRUE(o.heights.empty() && o.valid.empty());
  EXPECT_EQ(o.width, whole.field.width);
  EXPECT_EQ(o.height, whole.field.height);
  EXPECT_EQ(o.georef.geotransform, whole.field.georef.geotransform);
  EXPECT_EQ(o.georef.crs_wkt, whole.field.georef.crs_wkt);
  EXPECT_EQ(o.dx_per_row, whole.field.dx_per_row);
  EXPECT_EQ(o.dy, whole.field.dy);
  EXPECT_EQ(o.nodata, whole.field.nodata);
  EXPECT_EQ(a.result.nodata_count, whole.nodata_count);
  EXPECT_EQ(a.result.min_height, whole.min_height);
  EXPECT_EQ(a.result.max_height, whole.max_height);
  EXPECT_EQ(a.result.warnings, whole.warnings);
}

TEST(DemStrips, PutTogetherEqualTheWholeRead) {
  ScratchDir dir;
  RasterSpec north;  // 7 wide, 9 rows: strips of 4 leave one row, which joins the last strip
  north.width = 7;
  north.height = 9;
  north.values = ramp(7, 9, 100, 2, -3);
  north.values[10] = north.values[33] = north.values[40] = -9999;
  north.nodata = -9999;
  north.type = GDT_Int16;
  const std::string a = make_raster(dir.file("north.tif"), north);
  RasterSpec south = north;  // row 0 is the southern edge; stray NaN, warned of once
  south.type = GDT_Float32;
  south.nodata.reset();
  south.values = ramp(7, 9, 100, 1.5, -2.25);
  south.values[12] = south.values[50] = std::nan("");
  south.gt = {500000, 30, 0, 4000000, 0, 30};
  const std::string b = make_raster(dir.file("south.tif"), south);
  for (int rows : {1, 2, 3, 4, 8, 9, 40}) {
    expect_equals_whole_read({a}, rows);
    expect_equals_whole_read({b}, rows);
  }
  // The stray NaN warning is the whole file's, once.
  const Assembled s = assemble({b}, 2);
  ASSERT_EQ(s.result.warnings.size(), 1u);
  EXPECT_EQ(s.result.warnings[0].rfind("2 NaN pixel(s)", 0), 0u) << s.result.warnings[0];

  RasterSpec nw, se;  // a mosaic whose gaps are voids
  nw.values = ramp(4, 4, 100, 1, 0);
  se.values = ramp(4, 4, 200, 1, 0);
  se.gt[0] += 4 * 30;
  se.gt[3] -= 4 * 30;
  const std::vector<std::string> mosaic{make_raster(dir.file("nw.tif"), nw), make_raster(dir.file("se.tif"), se)};
  for (int rows : {2, 3, 5}) expect_equals_whole_read(mosaic, rows);
}

// Band 1 of a staged copy as raw bits (NaN payloads included).
std::vector<std::uint32_t> bits_of(const StagedDem& d) {
  GDALDataset& ds = d.dataset();
  const int w = ds.GetRasterXSize(), h = ds.GetRasterYSize();
  std::vector<float> v(static_cast<std::size_t>(w) * h);
  EXPECT_EQ(ds.GetRasterBand(1)->RasterIO(GF_Read, 0, 0, w, h, v.data(), w, h, GDT_Float32, 0, 0, nullptr), CE_None);
  std::vector<std::uint32_t> bits(v.size());
  std::memcpy(bits.data(), v.data(), v.size() * sizeof(float));
  return bits;
}

TEST(StagedDem, OnDiskEqualsInMemoryBitForBitAndLeavesNoFile) {
  ScratchDir dir, temp;
  RasterSpec s;  // south up, with voids: every conversion the copy must keep
  s.width = 37;
  s.height = 23;
  s.type = GDT_Int16;
  s.values = ramp(37, 23, 500, 3, 7);
  s.values[5] = s.values[300] = s.values[37 * 11 + 18] = -32768;  // [37·11+18]: the centre
  s.nodata = -32768;
  s.scale = 0.5;
  s.gt = {500000, 30, 0, 4000000, 0, 30};
  const std::string path = make_raster(dir.file("dem.tif"), s);
  const DemReadResult whole = read_dem(path);

  StagingOptions memory, disk;
  disk.memory_limit_bytes = 0;
  disk.directory = memory.directory = temp.path();
  disk.strip_pixels = memory.strip_pixels = 37 * 5;  // 5 rows a strip
  std::vector<std::string> warnings;
  const StagedDem in_memory = StagedDem::read({path}, {}, memory, warnings);
  const StagedDem on_disk = StagedDem::read({path}, {}, disk, warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_FALSE(in_memory.on_disk());
  ASSERT_TRUE(on_disk.on_disk());
  EXPECT_TRUE(temp.listing().empty()) << "the staged file is deleted once open";
  EXPECT_EQ(bits_of(on_disk), bits_of(in_memory));
  const StagedDem from_field = StagedDem::from_field(whole.field);
  EXPECT_EQ(bits_of(from_field), bits_of(in_memory));

  // Against read_dem: heights at valid pixels, NaN at voids, the same outline.
  const std::vector<std::uint32_t> bits = bits_of(on_disk);
  for (std::size_t k = 0; k < whole.field.size(); ++k) {
    float v;
    std::memcpy(&v, &bits[k], sizeof v);
    if (whole.field.valid[k]) {
      ASSERT_EQ(v, whole.field.heights[k]) << k;
    } else {
      ASSERT_TRUE(std::isnan(v)) << k;
    }
  }
  for (const StagedDem* d : {&in_memory, &on_disk, &from_field}) {
    EXPECT_EQ(d->valid_count(), whole.field.size() - 3);
    EXPECT_TRUE(d->has_voids());
    EXPECT_EQ(d->outline().georef.geotransform, whole.field.georef.geotransform);
    EXPECT_EQ(d->outline().nodata, whole.field.nodata);
    // The centre is a void: the lowest height, 500 · 0.5 (scale) at the south-west corner.
    EXPECT_EQ(d->centre_height(), 250.0f);
    double gt[6];
    ASSERT_EQ(d->dataset().GetGeoTransform(gt), CE_None);
    EXPECT_EQ(gt[3], whole.field.georef.geotransform[3]);
    EXPECT_EQ(gt[5], whole.field.georef.geotransform[5]);
  }
}

TEST(StagedDem, AReadThatFailsHalfWayLeavesNoFile) {
  ScratchDir dir, temp;
  RasterSpec s;
  s.width = 16;
  s.height = 40;
  s.values = ramp(16, 40, 100, 1, 1);
  s.values.back() = 20000;  // implausible, in the last strip: after the file was begun
  const std::string path = make_raster(dir.file("dem.tif"), s);
  StagingOptions disk;
  disk.memory_limit_bytes = 0;
  disk.directory = temp.path();
  disk.strip_pixels = 16 * 4;
  std::vector<std::string> warnings;
  try {
    StagedDem::read({path}, {}, disk, warnings);
    ADD_FAILURE() << "no DemError";
  } catch (const DemError& e) {
    EXPECT_NE(std::string(e.what()).find("implausible height 20000"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(temp.listing().empty());
  disk.directory = temp.path() / "missing";
  s.values.back() = 100;
  make_raster(path, s);
  try {
    StagedDem::read({path}, {}, disk, warnings);
    ADD_FAILURE() << "no DemError";
  } catch (const DemError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    EXPECT_NE(m.find("cannot stage the DEM in"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace skylit::terrain
