// `skylit tiles -w leaflet`: an index.html beside the output that shows the tiles on a
// Leaflet map (app/tiles/web/viewer.html, with Leaflet and the pmtiles reader inlined).
#pragma once

#include <array>
#include <string>

namespace skylit::app::tiles {

struct ViewerSpec {
  std::string title;
  enum class Kind { Pmtiles, Folder } kind = Kind::Folder;
  std::string url;  // relative to the page: the .pmtiles file, or the {z}/{x}/{y} folder
  bool tms = false;
  std::string format = "png";          // png, jpg or webp
  int tile_size = 256;
  int minzoom = 0, maxzoom = 0;
  std::array<double, 4> bounds{};     // west, south, east, north (degrees)
  std::string attribution;
};

// The page's HTML.
std::string leaflet_page(const ViewerSpec& spec);

// Writes index.html into `folder` atomically (app/common/text_file.h); throws
// std::runtime_error with a one-line message when it cannot.
void write_leaflet_viewer(const std::string& folder, const ViewerSpec& spec);

}  // namespace skylit::app::tiles
