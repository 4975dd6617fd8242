#include "tiles/reader.h"

#include "tiles/archive_kinds.h"

namespace skylit::tiles {

std::unique_ptr<TileReader> open_reader(const std::string& path) {
  switch (archive_kind(path)) {
    case ArchiveKind::MBTiles: return detail::open_mbtiles_reader(path);
    case ArchiveKind::PMTiles: return detail::open_pmtiles_reader(path);
    case ArchiveKind::Folder: break;
  }
  return detail::open_folder_reader(path);
}

}  // namespace skylit::tiles
