// The sink a tile run writes into (DESIGN.md "Map tiles"): tiles go in one at a time,
// in any order, from a run that may be killed at any moment and resumed; the metadata
// goes in last. Three kinds, picked by the output path: `*.mbtiles` (MBTiles 1.3),
// `*.pmtiles` (PMTiles v3), anything without an extension a folder {z}/{x}/{y}.EXT.
// An archive never exposes a partial tile: has() is true only for tiles that a resumed
// run may skip, and a file archive appears at its path only complete (finish()).
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>

#include "terrain/web_mercator.h"
#include "tiles/metadata.h"

namespace skylit::tiles {

// Tiles are addressed by the terrain grid's XYZ TileId (terrain/web_mercator.h, the one
// definition of the tile grid); TMS rows and PMTiles ids are derived where a format needs them.
using terrain::TileId;

// Every failure of this library; what() is one line naming the file and the problem.
// option(): the ArchiveOptions mode that would fix it ("overwrite", "resume"), or empty.
class TileArchiveError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
  TileArchiveError(const std::string& what, std::string option)
      : std::runtime_error(what), option_(std::move(option)) {}
  const std::string& option() const { return option_; }

 private:
  std::string option_;
};

enum class OpenMode {
  Create,     // the output (or an interrupted run's leftovers) must not exist
  Overwrite,  // start afresh; a file archive's old version stays until finish() replaces it
  Resume      // keep the complete tiles of an earlier run, finished or killed; creates if absent
};

enum class Scheme { Xyz, Tms };  // a folder's row order; MBTiles is TMS and PMTiles XYZ by spec

enum class ArchiveKind { Folder, MBTiles, PMTiles };

struct ArchiveOptions {
  OpenMode mode = OpenMode::Create;
  TileFormat format = TileFormat::Png;  // the folder's file extension; finish() must agree
  Scheme scheme = Scheme::Xyz;          // folders only
  // Tiles per SQLite transaction (MBTiles, PMTiles staging): a kill loses at most this many.
  int batch_tiles = 256;
  // PMTiles: the largest compressed root directory; the spec's 16 KiB minus the header.
  // Smaller values only serve tests of leaf directories.
  std::size_t pmtiles_max_root_bytes = 16384 - 127;
  // The run's options (tiles/fingerprint.h): recorded when the archive is opened, so an
  // interrupted run carries them too; Resume refuses an archive that records others,
  // before changing anything. Empty: nothing recorded or checked.
  std::string fingerprint{};
};

// Not thread-safe: one thread puts at a time (rendering may be parallel, storing is not).
// After an exception, destroy the archive and open it again with OpenMode::Resume.
class TileArchive {
 public:
  virtual ~TileArchive() = default;  // without finish(): what was put stays resumable
  // True when `t` was put by this run or by an earlier one that this run resumes.
  virtual bool has(const TileId& t) const = 0;
  // Stores `bytes` (non-empty) as tile `t`, replacing an earlier version.
  virtual void put(const TileId& t, std::span<const std::byte> bytes) = 0;
  // Writes the metadata and makes the archive complete at its path; nothing may follow.
  // PMTiles needs at least one tile.
  virtual void finish(const TileMetadata& metadata) = 0;
};

// The kind `path` names: ".mbtiles", ".pmtiles" (any case), or a folder when the last
// path component has no extension or the path ends in '/'. Throws TileArchiveError
// for any other extension ("out.zip").
ArchiveKind archive_kind(const std::string& path);

std::unique_ptr<TileArchive> open_archive(const std::string& path,
                                          const ArchiveOptions& options = {});

// std::span<const std::byte> over a string's bytes (tests, readers).
inline std::span<const std::byte> as_bytes(const std::string& s) {
  return std::as_bytes(std::span<const char>(s.data(), s.size()));
}

}  // namespace skylit::tiles
