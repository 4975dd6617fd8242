// Runs the built skylit binary through the shell for end-to-end CLI tests.
#pragma once

#include "terrain_test_util.h"

#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace skylit::testing {

struct Run {
  int status;       // exit code, −1 if the process did not exit normally
  std::string out;  // stdout (and stderr when merged)
};

// A shell command line; its stdout.
inline Run run_shell(const std::string& cmd) {
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return {-1, ""};
  std::string out;
  std::array<char, 4096> buf{};
  std::size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) out.append(buf.data(), n);
  const int raw = pclose(pipe);
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, out};
}

// Its stdout, and its stderr merged into it or left to the test's own stderr (shown on a
// failure).
inline Run run_skylit(const std::string& args, bool merge_stderr = false) {
  return run_shell(std::string(SKYLIT_BINARY) + " " + args + (merge_stderr ? " 2>&1" : ""));
}

// An output raster as the CLI wrote it, read back through GDAL: size, type of band 1,
// georeferencing, nodata and every band as float (band-major). w = 0 if unreadable.
struct OutputRaster {
  int w = 0, h = 0, bands = 0;
  GDALDataType type = GDT_Unknown;
  std::array<double, 6> gt{};
  std::string crs_name;
  int has_nodata = 0;
  double nodata = 0;
  std::vector<float> v;
  float at(int b, int i, int j) const { return v[(static_cast<std::size_t>(b) * h + j) * w + i]; }
  double mean(int b = 0) const {
    double s = 0;
    for (int k = 0; k < w * h; ++k) s += v[static_cast<std::size_t>(b) * w * h + k];
    return s / (w * h);
  }
};

inline OutputRaster read_output(const std::string& path) {
  terrain::testing::ensure_gdal();
  OutputRaster r;
  GDALDataset* ds = GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY);
  if (!ds) return r;
  r.w = ds->GetRasterXSize();
  r.h = ds->GetRasterYSize();
  r.bands = ds->GetRasterCount();
  r.type = ds->GetRasterBand(1)->GetRasterDataType();
  ds->GetGeoTransform(r.gt.data());
  if (ds->GetSpatialRef()) r.crs_name = ds->GetSpatialRef()->GetName();
  r.nodata = ds->GetRasterBand(1)->GetNoDataValue(&r.has_nodata);
  r.v.resize(static_cast<std::size_t>(r.w) * r.h * r.bands);
  for (int b = 0; b < r.bands; ++b)
    if (ds->GetRasterBand(b + 1)->RasterIO(GF_Read, 0, 0, r.w, r.h, r.v.data() + static_cast<std::size_t>(b) * r.w * r.h,
                                           r.w, r.h, GDT_Float32, 0, 0, nullptr) != CE_None)
      r.w = 0;
  GDALClose(GDALDataset::ToHandle(ds));
  return r;
}

inline int count_lines(const std::string& s) {
  int lines = 0;
  for (char c : s) lines += c == '\n';
  return lines;
}

// Expects `skylit shade ARGS -q` to fail cleanly: exit 1 (bad input) or 2 (bad usage),
// exactly one line starting "skylit: error:" that contains `needle`, and no file left
// behind in `dir`.
inline void expect_clean_shade_failure(const terrain::testing::ScratchDir& dir, const std::string& args,
                                       const std::string& needle) {
  const auto before = dir.listing();
  const auto r = run_skylit("shade " + args + " -q", true);
  EXPECT_TRUE(r.status == 1 || r.status == 2) << args << "\n" << r.out;
  EXPECT_EQ(count_lines(r.out), 1) << r.out;
  EXPECT_EQ(r.out.rfind("skylit: error: ", 0), 0u) << r.out;
  EXPECT_NE(r.out.find(needle), std::string::npos) << "expected '" << needle << "' in: " << r.out;
  EXPECT_EQ(dir.listing(), before) << "a failed run left files behind";
}

// The IGC track at `igc` with its fixes' latitude degrees set to 10 (the sample glider
// moved 36° south: nowhere near the synthetic scene), written to `out`; returns `out`.
inline std::string write_track_far_south(const std::string& igc, const std::string& out) {
  std::ifstream in(igc);
  std::ostringstream moved;
  for (std::string line; std::getline(in, line);) {
    if (line.size() > 8 && line[0] == 'B') line.replace(7, 2, "10");
    moved << line << "\n";
  }
  std::ofstream(out) << moved.str();
  return out;
}

}  // namespace skylit::testing
