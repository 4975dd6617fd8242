// The tile viewer's files (app/tiles/web/: the page template, Leaflet, the pmtiles
// reader), compiled into the binary at build time by cmake/embed_text_files.cmake, so
// `skylit tiles -w leaflet` writes a page that works offline.
#pragma once

#include <cstddef>
#include <string_view>

namespace skylit::app::tiles {

struct WebAsset {
  const char* name;  // file name inside app/tiles/web/, e.g. "leaflet.js"
  const char* text;  // its contents, verbatim
};

// The text of app/tiles/web/<name>; throws std::out_of_range naming the file if absent.
std::string_view web_asset(std::string_view name);

namespace detail {
extern const WebAsset kWebAssets[];
extern const std::size_t kWebAssetCount;
}  // namespace detail

}  // namespace skylit::app::tiles
