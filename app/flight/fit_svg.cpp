#include "app/flight/fit_svg.h"

#include "app/common/xml_escape.h"

#include "flight/fit_error.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace skylit::app::flight {
namespace {

using skylit::flight::BodySphere;
using skylit::flight::Mesh;

constexpr double kWidthPx = 900.0, kMarginPx = 24.0, kTitlePx = 28.0, kLabelPx = 18.0;

// One view: screen axes are two body axes (right, up); `toward` is the body direction
// toward the viewer, so only the triangles facing it are drawn (enough to fill a closed
// mesh's silhouette, and half the file).
struct View {
  const char* label;
  int right, up;
  glm::dvec3 toward;
};

}  // namespace

std::string fit_svg(const Mesh& mesh, const std::vector<BodySphere>& spheres, const std::string& title) {
  const skylit::flight::Bounds b = skylit::flight::bounds(mesh, spheres);
  const View views[] = {{"top (nose right, left wing up)", 0, 1, {0, 0, 1}},
                        {"side, from the right (nose right)", 0, 2, {0, -1, 0}}};
  const double extent_x = b.size().x;
  const double scale = (kWidthPx - 2 * kMarginPx) / std::max(extent_x, 1e-9);
  std::ostringstream body;
  double y0 = kMarginPx + kTitlePx;
  char buf[256];
  for (const View& v : views) {
    const double panel_h = b.size()[v.up] * scale;
    body << "<text x=\"" << kMarginPx << "\" y=\"" << y0 + 14 << "\" font-size=\"14\">" << v.label << "</text>\n";
    const double top = y0 + kLabelPx;
    auto sx = [&](const glm::dvec3& p) { return kMarginPx + (p[v.right] - b.lo[v.right]) * scale; };
    auto sy = [&](const glm::dvec3& p) { return top + (b.hi[v.up] - p[v.up]) * scale; };
    body << "<g fill=\"#9aa3ad\" stroke=\"#9aa3ad\" stroke-width=\"0.3\">\n";
    for (const auto& t : mesh.triangles) {
      const glm::dvec3 &p0 = mesh.vertices[t[0]], &p1 = mesh.vertices[t[1]], &p2 = mesh.vertices[t[2]];
      if (glm::dot(glm::cross(p1 - p0, p2 - p0), v.toward) <= 0.0) continue;
      std::snprintf(buf, sizeof buf, "<path d=\"M%.1f %.1fL%.1f %.1fL%.1f %.1fZ\"/>\n", sx(p0), sy(p0), sx(p1), sy(p1),
                    sx(p2), sy(p2));
      body << buf;
    }
    body << "</g>\n<g fill=\"#d9534f\" fill-opacity=\"0.25\" stroke=\"#b52b27\" stroke-width=\"1\">\n";
    for (const auto& s : spheres) {
      std::snprintf(buf, sizeof buf, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\"/>\n", sx(s.centre), sy(s.centre),
                    s.radius * scale);
      body << buf;
    }
    body << "</g>\n";
    y0 = top + panel_h + kMarginPx;
  }
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidthPx << "\" height=\"" << y0
      << "\" font-family=\"sans-serif\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<text x=\"" << kMarginPx
      << "\" y=\"" << kMarginPx + 6 << "\" font-size=\"16\">" << xml_escape(title) << "</text>\n"
      << body.str() << "</svg>\n";
  return svg.str();
}

}  // namespace skylit::app::flight
