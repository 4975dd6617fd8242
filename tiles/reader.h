// Reading a finished archive back: its metadata, its tile list and each tile's bytes.
// Enough for tests and merge(); not a tile server (whole lists, no caching).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tiles/archive.h"

namespace skylit::tiles {

class TileReader {
 public:
  virtual ~TileReader() = default;
  virtual const TileMetadata& metadata() const = 0;
  // Every tile the archive addresses, sorted (z, then x, then y); PMTiles runs expanded.
  virtual std::vector<TileId> tiles() const = 0;
  // The tile's bytes, or nullopt when the archive does not hold it.
  virtual std::optional<std::string> get(const TileId& t) const = 0;
};

// Opens the archive at `path` (kind from archive_kind()). A folder is read with the
// scheme its metadata.json records. Throws TileArchiveError when the archive is
// missing, unfinished (no metadata) or malformed.
std::unique_ptr<TileReader> open_reader(const std::string& path);

}  // namespace skylit::tiles
