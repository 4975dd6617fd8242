#include "tiles/metadata.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>

#include "tiles/archive.h"
#include "tiles/fingerprint.h"
#include "tiles/pmtiles_format.h"

namespace skylit::tiles {
namespace {

using nlohmann::json;

[[noreturn]] void bad(const std::string& what) { throw TileArchiveError("tile metadata: " + what); }

struct FormatName {
  TileFormat format;
  std::string_view name;
};
constexpr std::array kFormats{FormatName{TileFormat::Png, "png"}, FormatName{TileFormat::Jpeg, "jpg"},
                              FormatName{TileFormat::Webp, "webp"}};

}  // namespace

std::string_view format_name(TileFormat f) {
  for (const auto& e : kFormats)
    if (e.format == f) return e.name;
  return "?";
}

TileFormat parse_format(std::string_view name) {
  if (name == "jpeg") return TileFormat::Jpeg;
  for (const auto& e : kFormats)
    if (e.name == name) return e.format;
  bad("unknown tile format '" + std::string(name) + "' (png, jpg or webp)");
}

void validate(const TileMetadata& m) {
  if (m.name.empty()) bad("empty name");
  if (m.minzoom < 0 || m.maxzoom > terrain::kMaxTileZoom || m.minzoom > m.maxzoom)
    bad("zooms " + std::to_string(m.minzoom) + ".." + std::to_string(m.maxzoom) +
        " are not within 0.." + std::to_string(terrain::kMaxTileZoom));
  const Bounds& b = m.bounds;
  if (!(b.west >= -180 && b.east <= 180 && b.west <= b.east && b.south >= -90 && b.north <= 90 &&
        b.south <= b.north))
    bad("bounds are not W,S,E,N within the globe");
  if (!(std::abs(m.center.lon) <= 180 && std::abs(m.center.lat) <= 90) || m.center.zoom < 0 ||
      m.center.zoom > terrain::kMaxTileZoom)
    bad("center is not lon,lat,zoom within the globe and 0.." + std::to_string(terrain::kMaxTileZoom));
  if (m.type && *m.type != "overlay" && *m.type != "baselayer")
    bad("type '" + *m.type + "' is neither overlay nor baselayer");
}

std::string metadata_to_json(const TileMetadata& m, std::string_view extra_key,
                             std::string_view extra_value) {
  json j = {{"name", m.name},
            {"format", format_name(m.format)},
            {"bounds", {m.bounds.west, m.bounds.south, m.bounds.east, m.bounds.north}},
            {"center", {m.center.lon, m.center.lat, m.center.zoom}},
            {"minzoom", m.minzoom},
            {"maxzoom", m.maxzoom}};
  if (m.description) j["description"] = *m.description;
  if (m.attribution) j["attribution"] = *m.attribution;
  if (m.type) j["type"] = *m.type;
  if (m.fingerprint) j[kFingerprintKey] = *m.fingerprint;
  if (!extra_key.empty()) j[std::string(extra_key)] = extra_value;
  return j.dump();  // keys sorted: the same metadata gives the same bytes
}

double at_e7_precision(double degrees) { return pmtiles::to_e7(degrees) / 1e7; }

TileMetadata metadata_from_json(std::string_view text, const std::string& source) {
  const json j = json::parse(text, nullptr, false);
  if (!j.is_object()) throw TileArchiveError("'" + source + "': metadata is not a JSON object");
  try {
    TileMetadata m;
    m.name = j.at("name").get<std::string>();
    m.format = parse_format(j.at("format").get<std::string>());
    if (j.contains("bounds")) {
      const auto b = j["bounds"].get<std::array<double, 4>>();
      m.bounds = {b[0], b[1], b[2], b[3]};
    }
    if (j.contains("center")) {
      const auto c = j["center"].get<std::array<double, 3>>();
      m.center = {c[0], c[1], static_cast<int>(c[2])};
    }
    m.minzoom = j.value("minzoom", 0);
    m.maxzoom = j.value("maxzoom", 0);
    if (j.contains("description")) m.description = j["description"].get<std::string>();
    if (j.contains("attribution")) m.attribution = j["attribution"].get<std::string>();
    if (j.contains("type")) m.type = j["type"].get<std::string>();
    if (j.contains(kFingerprintKey)) m.fingerprint = j[kFingerprintKey].get<std::string>();
    return m;
  } catch (const json::exception& e) {
    throw TileArchiveError("'" + source + "': bad metadata: " + e.what());
  }
}

std::optional<std::string> json_string_member(std::string_view text, const std::string& key) {
  const json j = json::parse(text, nullptr, false);
  if (!j.is_object() || !j.contains(key) || !j[key].is_string()) return std::nullopt;
  return j[key].get<std::string>();
}

}  // namespace skylit::tiles
