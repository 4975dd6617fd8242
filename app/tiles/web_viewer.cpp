#include "app/tiles/web_viewer.h"

#include "app/common/text_file.h"
#include "app/common/xml_escape.h"
#include "app/tiles/web_assets.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string_view>

namespace skylit::app::tiles {
namespace {

// One pass over the template: text inserted for one marker is never searched again.
std::string fill(std::string_view page, const std::initializer_list<std::pair<std::string_view, std::string>>& marks) {
  std::string out;
  std::size_t at = 0;
  while (true) {
    std::size_t next = std::string_view::npos;
    const std::pair<std::string_view, std::string>* which = nullptr;
    for (const auto& m : marks)
      if (const std::size_t k = page.find(m.first, at); k < next) next = k, which = &m;
    if (!which) break;
    out.append(page, at, next - at).append(which->second);
    at = next + which->first.size();
  }
  return out.append(page.substr(at));
}

}  // namespace

std::string leaflet_page(const ViewerSpec& s) {
  nlohmann::json spec = {{"kind", s.kind == ViewerSpec::Kind::Pmtiles ? "pmtiles" : "folder"},
                         {"url", s.url},
                         {"tms", s.tms},
                         {"format", s.format},
                         {"tile_size", s.tile_size},
                         {"minzoom", s.minzoom},
                         {"maxzoom", s.maxzoom},
                         {"bounds", s.bounds},
                         {"attribution", s.attribution}};
  // "</" never appears in the JSON, so it cannot end the <script> it sits in.
  std::string json = spec.dump();
  for (std::size_t k = json.find("</"); k != std::string::npos; k = json.find("</", k)) json.replace(k, 2, "<\\/");
  return fill(web_asset("viewer.html"), {{"@TITLE@", xml_escape(s.title)},
                                         {"@LEAFLET_CSS@", std::string(web_asset("leaflet.css"))},
                                         {"@LEAFLET_JS@", std::string(web_asset("leaflet.js"))},
                                         {"@PMTILES_JS@", std::string(web_asset("pmtiles.js"))},
                                         {"@SPEC@", json}});
}

void write_leaflet_viewer(const std::string& folder, const ViewerSpec& spec) {
  write_text_atomically((std::filesystem::path(folder) / "index.html").string(), leaflet_page(spec), "the web viewer");
}

}  // namespace skylit::app::tiles
