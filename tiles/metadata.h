// What an archive says about its tiles: the TileJSON-like fields MBTiles 1.3 and
// PMTiles v3 both carry, and the image formats they may hold.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace skylit::tiles {

enum class TileFormat { Png, Jpeg, Webp };

// MBTiles' `format` value and the folder's file extension ("png", "jpg", "webp").
std::string_view format_name(TileFormat f);
// Accepts format_name's spellings and "jpeg"; throws TileArchiveError otherwise.
TileFormat parse_format(std::string_view name);

struct Bounds {  // degrees, WGS84
  double west = -180, south = -85.05112878, east = 180, north = 85.05112878;
  friend bool operator==(const Bounds&, const Bounds&) = default;
};

struct Center {
  double lon = 0, lat = 0;
  int zoom = 0;
  friend bool operator==(const Center&, const Center&) = default;
};

struct TileMetadata {
  std::string name;
  TileFormat format = TileFormat::Png;
  Bounds bounds;
  Center center;
  int minzoom = 0, maxzoom = 0;
  std::optional<std::string> description, attribution;
  std::optional<std::string> type;  // "overlay" or "baselayer"
  // The options the tiles were made with (tiles/fingerprint.h), when a skylit run wrote them.
  std::optional<std::string> fingerprint;
  friend bool operator==(const TileMetadata&, const TileMetadata&) = default;
};

// Degrees at the precision PMTiles' header keeps them (1e-7°, about a centimetre), which
// its reader reports: bounds and centres built with it read back the same from every
// kind, so a merge of shards writes the single run's metadata byte for byte.
double at_e7_precision(double degrees);

// Throws TileArchiveError naming the first field that no archive kind could store
// (empty name, zooms outside [0, terrain::kMaxTileZoom] or min > max, bounds off the globe, a type
// other than overlay/baselayer).
void validate(const TileMetadata& m);

// The metadata as one JSON object, the folder's metadata.json and PMTiles' metadata
// section: name, format, bounds [W,S,E,N], center [lon,lat,zoom], minzoom, maxzoom and
// the optional strings where set. `extra` members (e.g. "scheme") are merged in.
std::string metadata_to_json(const TileMetadata& m, std::string_view extra_key = {},
                             std::string_view extra_value = {});
// Parses metadata_to_json's output; `source` names the file in errors. Fields missing
// keep their defaults except name and format, which are required.
TileMetadata metadata_from_json(std::string_view json, const std::string& source);
// Reads one string member of a JSON object ("scheme"), or nullopt.
std::optional<std::string> json_string_member(std::string_view json, const std::string& key);

}  // namespace skylit::tiles
