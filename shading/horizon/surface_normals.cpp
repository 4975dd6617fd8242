#include "shading/horizon/surface_normals.h"

#include <algorithm>
#include <cmath>

namespace skylit::horizon {

glm::dvec3 horn_normal(const terrain::HeightField& f, int i, int j) {
  // Replicating the edge texel = clamping the neighbour index.
  auto h = [&](int di, int dj) {
    return static_cast<double>(f.at(std::clamp(i + di, 0, f.width - 1), std::clamp(j + dj, 0, f.height - 1)));
  };
  // Row j−1 is north of row j.
  const double dzdx = ((h(1, -1) + 2.0 * h(1, 0) + h(1, 1)) - (h(-1, -1) + 2.0 * h(-1, 0) + h(-1, 1))) / (8.0 * f.dx(j));
  const double dzdy = ((h(-1, -1) + 2.0 * h(0, -1) + h(1, -1)) - (h(-1, 1) + 2.0 * h(0, 1) + h(1, 1))) / (8.0 * f.dy);
  const double norm = std::sqrt(dzdx * dzdx + dzdy * dzdy + 1.0);
  return {-dzdx / norm, -dzdy / norm, 1.0 / norm};
}

std::vector<glm::dvec3> horn_normals(const terrain::HeightField& f) {
  std::vector<glm::dvec3> out(f.size());
  for (int j = 0; j < f.height; ++j)
    for (int i = 0; i < f.width; ++i) out[static_cast<std::size_t>(j) * f.width + i] = horn_normal(f, i, j);
  return out;
}

}  // namespace skylit::horizon
