#include "app/tiles/web_viewer.h"

#include "app/tiles/web_assets.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <unistd.h>

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

// Text safe inside an HTML <title>.
std::string html_escape(const std::string& s) {
  std::string out;
  for (const char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
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
  return fill(web_asset("viewer.html"), {{"@TITLE@", html_escape(s.title)},
                                         {"@LEAFLET_CSS@", std::string(web_asset("leaflet.css"))},
                                         {"@LEAFLET_JS@", std::string(web_asset("leaflet.js"))},
                                         {"@PMTILES_JS@", std::string(web_asset("pmtiles.js"))},
                                         {"@SPEC@", json}});
}

void write_leaflet_viewer(const std::string& folder, const ViewerSpec& spec) {
  namespace fs = std::filesystem;
  const fs::path final_path = fs::path(folder) / "index.html";
  const fs::path temp = fs::path(folder) / (".index.html.tmp-" + std::to_string(::getpid()));
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    out << leaflet_page(spec);
    out.close();
    if (!out) {
      std::error_code ec;
      fs::remove(temp, ec);
      throw std::runtime_error("cannot write the web viewer " + final_path.string());
    }
  }
  std::error_code ec;
  fs::rename(temp, final_path, ec);
  if (ec) {
    fs::remove(temp, ec);
    throw std::runtime_error("cannot write the web viewer " + final_path.string() + ": " + ec.message());
  }
}

}  // namespace skylit::app::tiles
