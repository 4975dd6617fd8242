// The height field as data: float32 heights in metres on a regular grid, metric
// spacing, nodata mask and the georeferencing needed to write outputs.
//
// Grid convention (GDAL's): column i grows east, row j grows south; row 0 is the
// northern edge. Texel (i, j) has its centre at map position
// (i·dx, −j·dy) in a local metric frame with x east, y north.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace skylit::terrain {

struct GeoReference {
  std::array<double, 6> geotransform{0, 1, 0, 0, 0, -1};  // GDAL order
  std::string crs_wkt;                                     // empty: unknown CRS
  bool geographic = false;                                 // CRS in degrees
};

struct HeightField {
  int width = 0;
  int height = 0;
  std::vector<float> heights;        // row-major, width·height, metres; nodata filled
  std::vector<std::uint8_t> valid;   // 1 = measured height, 0 = nodata (filled for marching)
  double dy = 1.0;                   // north–south spacing (m), same for every row
  std::vector<double> dx_per_row;    // east–west spacing (m) of each row
  std::optional<double> nodata;      // nodata value to write in outputs, if any
  GeoReference georef;

  HeightField() = default;
  HeightField(int w, int h, double spacing);  // flat, all valid, square spacing

  std::size_t size() const { return heights.size(); }
  float at(int i, int j) const { return heights[static_cast<std::size_t>(j) * width + i]; }
  float& at(int i, int j) { return heights[static_cast<std::size_t>(j) * width + i]; }
  bool is_valid(int i, int j) const { return valid[static_cast<std::size_t>(j) * width + i] != 0; }
  double dx(int j) const { return dx_per_row[j]; }
  double mean_dx() const;
  bool any_nodata() const;
};

}  // namespace skylit::terrain
