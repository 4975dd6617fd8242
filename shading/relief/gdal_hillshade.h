// gdaldem's hillshade (GDAL apps/gdaldem_lib.cpp), reproduced operation for operation so
// that the 8-bit result equals Debian's gdaldem 3.6 bit for bit (docs/gdaldem.md):
// regular, combined, multidirectional and Igor shading, Horn or Zevenbergen–Thorne
// gradients, z factor, the window's nodata rules and the optional edge extrapolation.
#pragma once

#include "terrain/height_field.h"

#include <vector>

namespace skylit::relief {

enum class Gradient { Horn, ZevenbergenThorne };
enum class HillshadeVariant { Regular, Combined, MultiDirectional, Igor };

struct HillshadeOptions {
  Gradient gradient = Gradient::Horn;
  HillshadeVariant variant = HillshadeVariant::Regular;
  double z = 1.0;               // applied inside the formula, as gdaldem does (heights unscaled)
  double azimuth_deg = 315.0;   // light from, clockwise from north (unused by multidirectional)
  double altitude_deg = 45.0;
  // false: the border rows and columns are nodata, as are texels with a nodata
  // neighbour; true: missing neighbours are extrapolated (2a − b) or take the centre.
  bool compute_edges = false;
};

// Shade values 1…255 as floats, row-major, NaN where gdaldem writes nodata. Spacing: the
// field's row spacing dy and the east–west spacing of its centre row (one scale for
// the whole grid, as gdaldem takes one per axis). Heights that are all integers take
// gdaldem's integer (Int16/UInt16/Byte) code path, others its Float32 path.
std::vector<float> gdal_hillshade(const terrain::HeightField& field, const HillshadeOptions& options);

}  // namespace skylit::relief
