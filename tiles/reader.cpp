#include "tiles/reader.h"

#include "tiles/archive_kinds.h"
#include "tiles/file_io.h"

namespace skylit::tiles {

std::unique_ptr<TileReader> open_reader(const std::string& path) {
  try {
    switch (archive_kind(path)) {
      case ArchiveKind::MBTiles: return detail::open_mbtiles_reader(path);
      case ArchiveKind::PMTiles: return detail::open_pmtiles_reader(path);
      case ArchiveKind::Folder: break;
    }
    return detail::open_folder_reader(path);
  } catch (const std::filesystem::filesystem_error& e) {
    detail::fail(path, e.code().message());
  }
}

}  // namespace skylit::tiles
