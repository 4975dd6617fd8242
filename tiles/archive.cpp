// Picking the archive kind from the output path, and the checks every kind shares.
#include "tiles/archive.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "tiles/archive_kinds.h"
#include "tiles/file_io.h"

namespace skylit::tiles {

namespace fs = std::filesystem;

ArchiveKind archive_kind(const std::string& path) {
  if (path.empty()) throw TileArchiveError("empty tile archive path");
  if (path.back() == '/') return ArchiveKind::Folder;
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext.empty()) return ArchiveKind::Folder;
  if (ext == ".mbtiles") return ArchiveKind::MBTiles;
  if (ext == ".pmtiles") return ArchiveKind::PMTiles;
  throw TileArchiveError("'" + path + "': unknown tile archive kind '" + ext +
                         "' (use .mbtiles, .pmtiles, or a folder name without an extension)");
}

std::unique_ptr<TileArchive> open_archive(const std::string& path, const ArchiveOptions& options) {
  try {
    switch (archive_kind(path)) {
      case ArchiveKind::MBTiles: return detail::open_mbtiles_archive(path, options);
      case ArchiveKind::PMTiles: return detail::open_pmtiles_archive(path, options);
      case ArchiveKind::Folder: break;
    }
    return detail::open_folder_archive(path, options);
  } catch (const fs::filesystem_error& e) {  // permissions and the like: still one line
    detail::fail(path, e.code().message());
  }
}

namespace detail {

void check_tile(const fs::path& archive, const TileId& t, std::span<const std::byte> bytes) {
  if (!is_valid(t)) fail(archive, "tile " + to_string(t) + " is outside its zoom's grid");
  if (bytes.empty()) fail(archive, "tile " + to_string(t) + " is empty");
}

void check_metadata(const fs::path& archive, const TileMetadata& m, const ArchiveOptions& options) {
  validate(m);
  if (m.format != options.format)
    fail(archive, "metadata format '" + std::string(format_name(m.format)) +
                      "' differs from the archive's '" + std::string(format_name(options.format)) + "'");
}

}  // namespace detail
}  // namespace skylit::tiles
