// Helpers for the terrain tests: a scratch directory and small GDAL rasters.
#pragma once

#include <gdal_priv.h>
#include <ogr_spatialref.h>
#include <sys/mount.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "terrain/height_field.h"

// Skips the test when `missing` (what it needs and lacks; "" when nothing) is not empty,
// but fails it where CI is set: CI runs every test. A macro, as GTEST_SKIP and FAIL
// return from the test body.
#define SKYLIT_REQUIRE(missing)                                           \
  do {                                                                    \
    const std::string skylit_missing_ = (missing);                        \
    if (!skylit_missing_.empty()) {                                       \
      if (std::getenv("CI")) FAIL() << skylit_missing_ << " (CI is set)"; \
      GTEST_SKIP() << skylit_missing_;                                    \
    }                                                                     \
  } while (0)

namespace skylit::terrain::testing {

namespace fs = std::filesystem;

// A fresh directory under the system temp dir, removed with everything in it.
class ScratchDir {
 public:
  ScratchDir() {
    static std::atomic<int> n{0};
    path_ = fs::temp_directory_path() /
            ("skylit_terrain_test_" + std::to_string(::getpid()) + "_" + std::to_string(n++));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::permissions(path_, fs::perms::owner_all, fs::perm_options::add, ec);
    fs::remove_all(path_, ec);
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const fs::path& path() const { return path_; }
  // Names of everything in the directory (to prove nothing was left behind).
  std::vector<std::string> listing() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(path_)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

 private:
  fs::path path_;
};

struct RasterSpec {
  int width = 4, height = 4;
  GDALDataType type = GDT_Float32;
  std::vector<double> values;                            // row-major; empty = zeros
  std::array<double, 6> gt{500000, 30, 0, 4000000, 0, -30};
  std::optional<int> epsg = 32611;                       // nullopt: no CRS
  bool set_geotransform = true;
  std::optional<double> nodata;
  std::optional<double> scale, offset;
  std::string unit;
  std::string driver = "GTiff";
};

inline void ensure_gdal() {
  static bool once = (GDALAllRegister(), true);
  (void)once;
}

inline std::string make_raster(const std::string& path, const RasterSpec& s) {
  ensure_gdal();
  GDALDriver* drv = GetGDALDriverManager()->GetDriverByName(s.driver.c_str());
  GDALDataset* ds = drv->Create(path.c_str(), s.width, s.height, 1, s.type, nullptr);
  if (!ds) throw std::runtime_error("test helper: cannot create " + path);
  if (s.set_geotransform) {
    double gt[6];
    std::copy(s.gt.begin(), s.gt.end(), gt);
    ds->SetGeoTransform(gt);
  }
  if (s.epsg) {
    OGRSpatialReference srs;
    srs.importFromEPSG(*s.epsg);
    ds->SetSpatialRef(&srs);
  }
  GDALRasterBand* b = ds->GetRasterBand(1);
  if (s.nodata) b->SetNoDataValue(*s.nodata);
  if (s.scale) b->SetScale(*s.scale);
  if (s.offset) b->SetOffset(*s.offset);
  if (!s.unit.empty()) b->SetUnitType(s.unit.c_str());
  std::vector<double> v = s.values;
  v.resize(static_cast<std::size_t>(s.width) * s.height, 0.0);
  if (b->RasterIO(GF_Write, 0, 0, s.width, s.height, v.data(), s.width, s.height, GDT_Float64, 0, 0, nullptr) !=
      CE_None)
    throw std::runtime_error("test helper: cannot write " + path);
  GDALClose(GDALDataset::ToHandle(ds));
  return path;
}

// A ramp z = a + bx·i + by·j, row-major.
inline std::vector<double> ramp(int w, int h, double a, double bx, double by) {
  std::vector<double> v(static_cast<std::size_t>(w) * h);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) v[static_cast<std::size_t>(j) * w + i] = a + bx * i + by * j;
  return v;
}

// An 8 × 8 ramp with neither CRS nor geotransform (needs -s / --lat/--lon to be used).
inline std::string make_crs_less_ramp(const std::string& path) {
  RasterSpec s;
  s.width = s.height = 8;
  s.values = ramp(8, 8, 10, 1, 2);
  s.epsg.reset();
  s.set_geotransform = false;
  return make_raster(path, s);
}

// A tmpfs of `size` ("64k") mounted at `at` for full-disk tests, unmounted at the end.
// Mounting needs root (CAP_SYS_ADMIN): check mounted() with SKYLIT_REQUIRE.
class Tmpfs {
 public:
  Tmpfs(const fs::path& at, const std::string& size) : at_(at) {
    fs::create_directories(at);
    mounted_ = ::mount("tmpfs", at.c_str(), "tmpfs", 0, ("size=" + size).c_str()) == 0;
  }
  ~Tmpfs() {
    if (mounted_) ::umount2(at_.c_str(), MNT_DETACH);
  }
  Tmpfs(const Tmpfs&) = delete;
  Tmpfs& operator=(const Tmpfs&) = delete;
  bool mounted() const { return mounted_; }
  bool resize(const std::string& size) {
    return ::mount("tmpfs", at_.c_str(), "tmpfs", MS_REMOUNT, ("size=" + size).c_str()) == 0;
  }
  // Root writes anywhere except on a read-only file system.
  bool make_read_only() { return ::mount("tmpfs", at_.c_str(), "tmpfs", MS_REMOUNT | MS_RDONLY, nullptr) == 0; }

 private:
  fs::path at_;
  bool mounted_ = false;
};

// A georeference in EPSG `epsg` with geotransform `gt`.
inline GeoReference epsg_georef(int epsg, const std::array<double, 6>& gt) {
  GeoReference g;
  g.has_geotransform = true;
  g.geotransform = gt;
  OGRSpatialReference srs;
  srs.importFromEPSG(epsg);
  char* wkt = nullptr;
  srs.exportToWkt(&wkt);
  g.crs_wkt = wkt;
  CPLFree(wkt);
  return g;
}

// The georeference of RasterSpec's default grid: 30 m UTM 11N texels from (500000, 4000000).
inline GeoReference utm_georef() { return epsg_georef(32611, {500000, 30, 0, 4000000, 0, -30}); }

inline std::string shared_dem(const std::string& name) { return std::string(SKYLIT_SHARED_DIR) + "/dem/" + name; }

// "" when `path` exists, else "<path> is missing" (for SKYLIT_REQUIRE).
inline std::string missing_file(const std::string& path) {
  return fs::exists(path) ? std::string() : path + " is missing";
}

}  // namespace skylit::terrain::testing
