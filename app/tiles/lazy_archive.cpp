#include "app/tiles/lazy_archive.h"

#include <stdexcept>
#include <utility>

namespace skylit::app::tiles {

LazyArchive::LazyArchive(std::string path, const skylit::tiles::ArchiveOptions& options)
    : path_(std::move(path)), options_(options) {
  if (options_.mode == skylit::tiles::OpenMode::Resume) archive_ = skylit::tiles::open_archive(path_, options_);
}

void LazyArchive::put(const skylit::tiles::TileId& t, std::span<const std::byte> bytes) {
  if (!archive_) archive_ = skylit::tiles::open_archive(path_, options_);
  archive_->put(t, bytes);
}

void LazyArchive::finish(const skylit::tiles::TileMetadata& metadata) {
  if (!archive_) throw std::logic_error("tiles: finish() of an archive never opened");
  archive_->finish(metadata);
}

}  // namespace skylit::app::tiles
