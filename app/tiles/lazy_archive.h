// The run's archive, opened at its first tile rather than before rendering: a run that
// finds nothing to write (a shard whose tiles all lie outside the DEM) then leaves no
// output behind. A resumed run opens it at once, since has() needs the earlier tiles.
#pragma once

#include <memory>
#include <span>
#include <string>

#include "tiles/archive.h"

namespace skylit::app::tiles {

class LazyArchive {
 public:
  LazyArchive(std::string path, const skylit::tiles::ArchiveOptions& options);
  bool has(const skylit::tiles::TileId& t) const { return archive_ && archive_->has(t); }
  void put(const skylit::tiles::TileId& t, std::span<const std::byte> bytes);
  bool opened() const { return archive_ != nullptr; }
  // Throws std::logic_error when nothing was ever opened (check opened() first).
  void finish(const skylit::tiles::TileMetadata& metadata);

 private:
  std::string path_;
  skylit::tiles::ArchiveOptions options_;
  std::unique_ptr<skylit::tiles::TileArchive> archive_;
};

}  // namespace skylit::app::tiles
