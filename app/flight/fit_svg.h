// A picture of a sphere fit: top and side views of the spheres over the mesh's
// silhouette, as SVG text.
#pragma once

#include "flight/mesh.h"
#include "flight/sphere_set.h"

#include <string>
#include <vector>

namespace skylit::app::flight {

std::string fit_svg(const skylit::flight::Mesh& mesh, const std::vector<skylit::flight::BodySphere>& spheres,
                    const std::string& title);

}  // namespace skylit::app::flight
