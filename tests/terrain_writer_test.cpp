// Raster writer: round trips (GTiff, COG, PNG), layouts, georeference and nodata, and
// atomicity: every failure leaves the output directory exactly as it was.
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

#include "terrain/dem_reader.h"
#include "terrain/raster_writer.h"
#include "terrain_test_util.h"

namespace skylit::terrain {
namespace {

using testing::ScratchDir;

using testing::utm_georef;

struct Opened {
  GDALDataset* ds;
  explicit Opened(const std::string& p) : ds(GDALDataset::Open(p.c_str(), GDAL_OF_RASTER)) {}
  ~Opened() {
    if (ds) GDALClose(GDALDataset::ToHandle(ds));
  }
};

template <class T>
std::vector<T> read_band(GDALDataset* ds, int b, GDALDataType type) {
  std::vector<T> v(static_cast<std::size_t>(ds->GetRasterXSize()) * ds->GetRasterYSize());
  EXPECT_EQ(ds->GetRasterBand(b)->RasterIO(GF_Read, 0, 0, ds->GetRasterXSize(), ds->GetRasterYSize(), v.data(),
                                           ds->GetRasterXSize(), ds->GetRasterYSize(), type, 0, 0, nullptr),
            CE_None);
  return v;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const RasterWriteError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    return m;
  }
  ADD_FAILURE() << "no RasterWriteError thrown";
  return {};
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

TEST(TerrainWriter, Float32MultibandGeoTiff) {
  testing::ensure_gdal();
  ScratchDir dir;
  const int w = 5, h = 3, bands = 2;
  std::vector<float> data(w * h * bands);
  for (std::size_t k = 0; k < data.size(); ++k) data[k] = 0.25f * k;
  RasterWriteOptions o;
  o.nodata = -9999;
  o.band_descriptions = {"azimuth 0", "azimuth 180"};
  o.creation_options = {"COMPRESS=DEFLATE"};
  const auto g = utm_georef();
  write_raster(dir.file("out.tif"), g, w, h, bands, std::span<const float>(data), o);
  EXPECT_EQ(dir.listing(), std::vector<std::string>{"out.tif"});
  Opened in(dir.file("out.tif"));
  ASSERT_TRUE(in.ds);
  EXPECT_EQ(in.ds->GetRasterCount(), 2);
  double gt[6];
  in.ds->GetGeoTransform(gt);
  for (int k = 0; k < 6; ++k) EXPECT_DOUBLE_EQ(gt[k], g.geotransform[k]);
  ASSERT_TRUE(in.ds->GetSpatialRef());
  EXPECT_STREQ(in.ds->GetSpatialRef()->GetAuthorityCode(nullptr), "32611");
  int has = 0;
  EXPECT_EQ(in.ds->GetRasterBand(2)->GetNoDataValue(&has), -9999);
  EXPECT_TRUE(has);
  EXPECT_STREQ(in.ds->GetRasterBand(2)->GetDescription(), "azimuth 180");
  const auto b2 = read_band<float>(in.ds, 2, GDT_Float32);
  for (int k = 0; k < w * h; ++k) EXPECT_EQ(b2[k], data[w * h + k]);
}

TEST(TerrainWriter, InterleavedRgbPngWithGeoreference) {
  testing::ensure_gdal();
  ScratchDir dir;
  const int w = 4, h = 2;
  std::vector<std::uint8_t> rgb(w * h * 3);
  for (int k = 0; k < w * h; ++k) rgb[3 * k] = k, rgb[3 * k + 1] = 100 + k, rgb[3 * k + 2] = 200 + k;
  RasterWriteOptions o;
  o.format = "PNG";
  o.layout = SampleLayout::PixelInterleaved;
  write_raster(dir.file("img.png"), utm_georef(), w, h, 3, std::span<const std::uint8_t>(rgb), o);
  // Georeference lives in the PAM sidecar, which must have been moved along.
  EXPECT_EQ(dir.listing(), (std::vector<std::string>{"img.png", "img.png.aux.xml"}));
  Opened in(dir.file("img.png"));
  ASSERT_TRUE(in.ds);
  EXPECT_EQ(in.ds->GetRasterCount(), 3);
  EXPECT_EQ(in.ds->GetRasterBand(1)->GetColorInterpretation(), GCI_RedBand);
  const auto green = read_band<std::uint8_t>(in.ds, 2, GDT_Byte);
  for (int k = 0; k < w * h; ++k) EXPECT_EQ(green[k], 100 + k);
  double gt[6];
  ASSERT_EQ(in.ds->GetGeoTransform(gt), CE_None);
  EXPECT_DOUBLE_EQ(gt[0], 500000);
}

TEST(TerrainWriter, CloudOptimizedGeoTiff) {
  testing::ensure_gdal();
  ScratchDir dir;
  const int w = 300, h = 200;
  std::vector<float> data(w * h, 1.5f);
  RasterWriteOptions o;
  o.format = "COG";
  o.creation_options = {"COMPRESS=DEFLATE", "BLOCKSIZE=256"};
  std::vector<double> progress;
  o.progress = [&](double f) { progress.push_back(f); return true; };
  write_raster(dir.file("c.tif"), utm_georef(), w, h, 1, std::span<const float>(data), o);
  EXPECT_EQ(dir.listing(), std::vector<std::string>{"c.tif"});
  Opened in(dir.file("c.tif"));
  ASSERT_TRUE(in.ds);
  const char* layout = in.ds->GetMetadataItem("LAYOUT", "IMAGE_STRUCTURE");
  ASSERT_TRUE(layout);
  EXPECT_STREQ(layout, "COG");
  ASSERT_FALSE(progress.empty());
  EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end()));
  EXPECT_DOUBLE_EQ(progress.back(), 1.0);
}

TEST(TerrainWriter, HeightFieldRoundTripWritesNodata) {
  ScratchDir dir;
  HeightField f(6, 4, 30.0);
  f.georef = utm_georef();
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 6; ++i) f.at(i, j) = 100.0f + i + 10 * j;
  f.valid[7] = 0;
  f.nodata = -32768;
  write_height_field(dir.file("hf.tif"), f);
  const auto r = read_dem(dir.file("hf.tif"));
  EXPECT_EQ(r.nodata_count, 1u);
  EXPECT_EQ(r.field.valid[7], 0);
  EXPECT_FLOAT_EQ(r.field.at(5, 3), 135.0f);
  EXPECT_DOUBLE_EQ(r.field.dx(0), 30.0);
}

// ---- failures leave nothing behind ----

TEST(TerrainWriter, MissingDirectory) {
  ScratchDir dir;
  std::vector<float> d(4, 0.f);
  const auto m = error_of([&] { write_raster(dir.file("no/such/out.tif"), {}, 2, 2, 1, std::span<const float>(d)); });
  EXPECT_TRUE(contains(m, "does not exist")) << m;
  EXPECT_TRUE(dir.listing().empty());
}

TEST(TerrainWriter, UnwritableDirectory) {
  ScratchDir dir;
  testing::fs::create_directory(dir.path() / "ro");
  // Root ignores permissions: a read-only file system there instead.
  std::optional<testing::Tmpfs> read_only;
  if (::geteuid() == 0) {
    read_only.emplace(dir.path() / "ro", "64k");
    SKYLIT_REQUIRE(read_only->mounted() && read_only->make_read_only() ? "" : "root, and no read-only tmpfs could be mounted");
  } else {
    testing::fs::permissions(dir.path() / "ro", testing::fs::perms::owner_read | testing::fs::perms::owner_exec);
  }
  std::vector<float> d(4, 0.f);
  const auto m = error_of([&] { write_raster(dir.file("ro/out.tif"), {}, 2, 2, 1, std::span<const float>(d)); });
  EXPECT_TRUE(contains(m, "not writable")) << m;
  if (!read_only) testing::fs::permissions(dir.path() / "ro", testing::fs::perms::owner_all);
  EXPECT_TRUE(testing::fs::is_empty(dir.path() / "ro"));
}

TEST(TerrainWriter, ParentIsAFile) {
  ScratchDir dir;
  std::ofstream(dir.file("plain")) << "x";
  std::vector<float> d(4, 0.f);
  const auto m = error_of([&] { write_raster(dir.file("plain/out.tif"), {}, 2, 2, 1, std::span<const float>(d)); });
  EXPECT_TRUE(contains(m, "is not a directory")) << m;
  EXPECT_EQ(dir.listing(), std::vector<std::string>{"plain"});
}

TEST(TerrainWriter, BadRequestsLeaveNothing) {
  ScratchDir dir;
  std::vector<float> d(4, 1.f);
  std::vector<std::uint8_t> b(4, 1);
  const auto out = dir.file("out.tif");
  RasterWriteOptions png;
  png.format = "PNG";
  EXPECT_TRUE(contains(error_of([&] { write_raster(dir.file("f.png"), {}, 2, 2, 1, std::span<const float>(d), png); }),
                       "cannot store Float32"));
  RasterWriteOptions bogus;
  bogus.format = "NoSuchFormat";
  EXPECT_TRUE(contains(error_of([&] { write_raster(out, {}, 2, 2, 1, std::span<const float>(d), bogus); }),
                       "unknown raster format"));
  RasterWriteOptions co;
  co.creation_options = {"COMPRESS=NOT_A_CODEC"};
  EXPECT_TRUE(contains(error_of([&] { write_raster(out, {}, 2, 2, 1, std::span<const float>(d), co); }),
                       "invalid creation option"));
  co.creation_options = {"JUSTANAME"};
  EXPECT_TRUE(contains(error_of([&] { write_raster(out, {}, 2, 2, 1, std::span<const float>(d), co); }),
                       "NAME=VALUE"));
  EXPECT_TRUE(contains(error_of([&] { write_raster(out, {}, 3, 2, 1, std::span<const float>(d)); }),
                       "expected width·height·bands"));
  RasterWriteOptions nd;
  nd.nodata = 300;
  EXPECT_TRUE(contains(error_of([&] { write_raster(out, {}, 2, 2, 1, std::span<const std::uint8_t>(b), nd); }),
                       "0…255"));
  EXPECT_TRUE(dir.listing().empty());
}

TEST(TerrainWriter, CancelledWriteKeepsTheOldFile) {
  ScratchDir dir;
  const auto out = dir.file("keep.tif");
  std::ofstream(out) << "previous output";
  const int w = 512, h = 512;
  std::vector<float> d(w * h, 2.f);
  for (const char* format : {"GTiff", "COG"}) {
    RasterWriteOptions o;
    o.format = format;
    o.progress = [](double f) { return f < 0.2; };  // cancel part-way
    EXPECT_TRUE(contains(error_of([&] { write_raster(out, {}, w, h, 1, std::span<const float>(d), o); }),
                         "cancel"));
    EXPECT_EQ(dir.listing(), std::vector<std::string>{"keep.tif"});
    std::ifstream in(out);
    std::string content;
    std::getline(in, content);
    EXPECT_EQ(content, "previous output");
  }
  RasterWriteOptions no_overwrite;
  no_overwrite.overwrite = false;
  EXPECT_TRUE(contains(error_of([&] { write_raster(out, {}, w, h, 1, std::span<const float>(d), no_overwrite); }),
                       "exists"));
}

TEST(TerrainWriter, OverwriteReplacesAtomically) {
  testing::ensure_gdal();
  ScratchDir dir;
  const auto out = dir.file("o.tif");
  std::vector<float> a(4, 1.f), b(4, 2.f);
  write_raster(out, utm_georef(), 2, 2, 1, std::span<const float>(a));
  write_raster(out, utm_georef(), 2, 2, 1, std::span<const float>(b));
  EXPECT_EQ(dir.listing(), std::vector<std::string>{"o.tif"});
  Opened in(out);
  EXPECT_EQ(read_band<float>(in.ds, 1, GDT_Float32)[3], 2.f);
}

}  // namespace
}  // namespace skylit::terrain
