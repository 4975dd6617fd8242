// The three archive kinds behind open_archive() and open_reader() (internal).
#pragma once

#include <filesystem>
#include <memory>

#include "tiles/archive.h"
#include "tiles/reader.h"

namespace skylit::tiles::detail {

std::unique_ptr<TileArchive> open_folder_archive(const std::filesystem::path& root,
                                                 const ArchiveOptions& options);
std::unique_ptr<TileReader> open_folder_reader(const std::filesystem::path& root);

std::unique_ptr<TileArchive> open_mbtiles_archive(const std::filesystem::path& path,
                                                  const ArchiveOptions& options);
std::unique_ptr<TileReader> open_mbtiles_reader(const std::filesystem::path& path);

std::unique_ptr<TileArchive> open_pmtiles_archive(const std::filesystem::path& path,
                                                  const ArchiveOptions& options);
std::unique_ptr<TileReader> open_pmtiles_reader(const std::filesystem::path& path);

// Checks put()'s arguments the same way for every kind.
void check_tile(const std::filesystem::path& archive, const TileId& t,
                std::span<const std::byte> bytes);
// Checks finish()'s metadata (validate() and the format the archive was opened with).
void check_metadata(const std::filesystem::path& archive, const TileMetadata& m,
                    const ArchiveOptions& options);

}  // namespace skylit::tiles::detail
