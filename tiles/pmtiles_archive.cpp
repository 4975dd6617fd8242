// PMTiles v3. Its directories need every tile before any can be written, so a run
// stages tiles in an SQLite database "OUT.partial" (tile id → bytes, committed in
// batches: the same kill -9 guarantees as MBTiles) and finish() assembles the archive
// into "OUT.assembling", syncs it and renames it over OUT, then drops the staging. OUT
// is thus always absent, the old archive or the new one; the staging database is what
// a resumed run continues. Assembly is a pure function of the staged tiles and the
// metadata, so shards merged and a single run give byte-identical archives.
#include <fcntl.h>

#include <algorithm>
#include <fstream>
#include <optional>
#include <unordered_map>

#include "tiles/archive_kinds.h"
#include "tiles/file_io.h"
#include "tiles/fingerprint.h"
#include "tiles/partial_database.h"
#include "tiles/pmtiles_format.h"
#include "tiles/sqlite_db.h"

namespace skylit::tiles::detail {
namespace {

namespace fs = std::filesystem;
using pmtiles::Entry;

// run: the run's options (tiles/fingerprint.h), one row at most.
constexpr const char* kSchema =
    "CREATE TABLE IF NOT EXISTS staged (tile_id integer PRIMARY KEY, data blob NOT NULL);"
    "CREATE TABLE IF NOT EXISTS run (fingerprint text NOT NULL);";

// nullopt also for a staging database that predates the table.
std::optional<std::string> staged_fingerprint(Database& db) {
  if (!Statement(db, "SELECT 1 FROM sqlite_master WHERE name = 'run'").step()) return std::nullopt;
  Statement get(db, "SELECT fingerprint FROM run");
  return get.step() ? std::optional(get.column_text(0)) : std::nullopt;
}

std::optional<std::string> finished_fingerprint(const fs::path& out) {
  return open_pmtiles_reader(out)->metadata().fingerprint;
}

std::uint64_t fnv1a(std::string_view s) {  // content key for deduplication (bytes compared too)
  std::uint64_t h = 14695981039346656037ull;
  for (char c : s) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
  return h;
}

// Resuming a finished archive: its tiles become the staging database, built beside it
// and renamed, so a kill during the import leaves no half-filled staging behind.
void import_archive(const fs::path& out, const fs::path& staging) {
  const fs::path temp = with_suffix(out, kAssemblySuffix);
  remove_database(temp);
  {
    const auto reader = open_pmtiles_reader(out);
    Database db(temp);
    db.exec(kSchema);
    db.exec("BEGIN");
    if (const auto& fp = reader->metadata().fingerprint)
      Statement(db, "INSERT INTO run (fingerprint) VALUES (?)").bind(1, *fp).run();
    Statement put(db, "INSERT INTO staged (tile_id, data) VALUES (?, ?)");
    for (const auto& t : reader->tiles()) {
      const std::string bytes = *reader->get(t);
      put.bind(1, static_cast<std::int64_t>(pmtiles::tile_id(t))).bind_blob(2, as_bytes(bytes)).run();
    }
    db.exec("COMMIT");
  }
  std::error_code ec;
  fs::rename(temp, staging, ec);
  if (ec) fail(staging, "cannot rename into place: " + ec.message());
}

class PMTilesArchive final : public TileArchive {
 public:
  PMTilesArchive(const fs::path& out, const ArchiveOptions& options)
      : out_(out), options_(options),
        db_(prepare_partial(out, options.mode, import_archive, finished_fingerprint, options.fingerprint)),
        batch_(db_, options.batch_tiles) {
    const bool fresh = !Statement(db_, "SELECT 1 FROM sqlite_master WHERE name = 'staged'").step();
    // Checked before the schema, so that a refused resume leaves the staging as it was.
    if (!fresh && options_.mode == OpenMode::Resume && !options_.fingerprint.empty())
      check_resume_fingerprint(out_, staged_fingerprint(db_), options_.fingerprint);
    db_.exec(kSchema);
    // A new staging records the options now, so that a killed run's staging carries them.
    if (!options_.fingerprint.empty() && !staged_fingerprint(db_))
      Statement(db_, "INSERT INTO run (fingerprint) VALUES (?)").bind(1, options_.fingerprint).run();
    has_.emplace(db_, "SELECT 1 FROM staged WHERE tile_id = ?");
    put_.emplace(db_, "INSERT OR REPLACE INTO staged (tile_id, data) VALUES (?, ?)");
  }

  bool has(const TileId& t) const override {
    if (!is_valid(t)) return false;
    has_->bind(1, static_cast<std::int64_t>(pmtiles::tile_id(t)));
    const bool found = has_->step();
    has_->reset();
    return found;
  }

  void put(const TileId& t, std::span<const std::byte> bytes) override {
    if (finished_) fail(out_, "put after finish");
    check_tile(out_, t, bytes);
    if (bytes.size() > UINT32_MAX) fail(out_, "tile " + to_string(t) + " exceeds 4 GiB");
    batch_.begin();
    put_->bind(1, static_cast<std::int64_t>(pmtiles::tile_id(t))).bind_blob(2, bytes).run();
    batch_.wrote();
  }

  void finish(const TileMetadata& m) override {
    if (finished_) fail(out_, "finished twice");
    check_metadata(out_, m, options_);
    batch_.commit();
    assemble(m);
    has_.reset();
    put_.reset();
    const fs::path staging = db_.path();
    db_.close();
    remove_database(staging);
    finished_ = true;
  }

 private:
  struct Layout {
    std::vector<Entry> entries;
    std::vector<std::uint64_t> first_ids;  // the tile whose bytes each stored content is
    std::uint64_t addressed = 0, data_length = 0;
  };

  // One pass over the staged tiles in tile-id order: identical bytes are stored once
  // (hash, then compared), and consecutive ids with the same content share one entry.
  Layout layout() {
    Layout l;
    std::unordered_map<std::uint64_t, std::vector<std::size_t>> by_hash;  // → index in first_ids
    std::vector<std::uint64_t> offsets;                                   // per content
    Statement all(db_, "SELECT tile_id, data FROM staged ORDER BY tile_id");
    Statement one(db_, "SELECT data FROM staged WHERE tile_id = ?");
    while (all.step()) {
      const auto id = static_cast<std::uint64_t>(all.column_int(0));
      const std::string bytes = all.column_text(1);
      auto& same_hash = by_hash[fnv1a(bytes)];
      std::optional<std::size_t> content;
      for (std::size_t c : same_hash) {
        one.bind(1, static_cast<std::int64_t>(l.first_ids[c]));
        const bool equal = one.step() && one.column_text(0) == bytes;
        one.reset();
        if (equal) content = c;
        if (equal) break;
      }
      if (!content) {
        content = l.first_ids.size();
        same_hash.push_back(*content);
        l.first_ids.push_back(id);
        offsets.push_back(l.data_length);
        l.data_length += bytes.size();
      }
      const std::uint64_t offset = offsets[*content];
      ++l.addressed;
      if (!l.entries.empty()) {
        Entry& last = l.entries.back();
        if (last.tile_id + last.run_length == id && last.offset == offset) {
          ++last.run_length;
          continue;
        }
      }
      l.entries.push_back({id, offset, static_cast<std::uint32_t>(bytes.size()), 1});
    }
    if (l.entries.empty()) fail(out_, "no tiles were put (PMTiles needs at least one)");
    return l;
  }

  void assemble(const TileMetadata& m) {
    const Layout l = layout();
    const auto dirs = pmtiles::build_directories(l.entries, options_.pmtiles_max_root_bytes);
    const std::string json = pmtiles::gzip(metadata_to_json(m));
    pmtiles::Header h;
    h.root_offset = pmtiles::kHeaderBytes;
    h.root_length = dirs.root.size();
    h.metadata_offset = h.root_offset + h.root_length;
    h.metadata_length = json.size();
    h.leaves_offset = h.metadata_offset + h.metadata_length;
    h.leaves_length = dirs.leaves.size();
    h.data_offset = h.leaves_offset + h.leaves_length;
    h.data_length = l.data_length;
    h.addressed_tiles = l.addressed;
    h.tile_entries = l.entries.size();
    h.tile_contents = l.first_ids.size();
    h.clustered = true;
    h.tile_type = pmtiles::tile_type(m.format);
    h.min_zoom = static_cast<std::uint8_t>(m.minzoom);
    h.max_zoom = static_cast<std::uint8_t>(m.maxzoom);
    h.min_lon_e7 = pmtiles::to_e7(m.bounds.west);
    h.min_lat_e7 = pmtiles::to_e7(m.bounds.south);
    h.max_lon_e7 = pmtiles::to_e7(m.bounds.east);
    h.max_lat_e7 = pmtiles::to_e7(m.bounds.north);
    h.center_zoom = static_cast<std::uint8_t>(m.center.zoom);
    h.center_lon_e7 = pmtiles::to_e7(m.center.lon);
    h.center_lat_e7 = pmtiles::to_e7(m.center.lat);

    const fs::path temp = with_suffix(out_, kAssemblySuffix);
    try {
      File f(temp, O_WRONLY | O_CREAT | O_TRUNC, 0644, out_);
      f.write(pmtiles::encode_header(h) + dirs.root + json + dirs.leaves);
      Statement all(db_, "SELECT tile_id, data FROM staged ORDER BY tile_id");
      std::size_t next = 0;  // index in first_ids: contents go out in tile-id order
      while (next < l.first_ids.size() && all.step()) {
        if (static_cast<std::uint64_t>(all.column_int(0)) != l.first_ids[next]) continue;
        f.write(all.column_text(1));
        ++next;
      }
      f.sync();
      f.close();
      std::error_code ec;
      fs::rename(temp, out_, ec);
      if (ec) fail(out_, "cannot rename '" + temp.string() + "' into place: " + ec.message());
    } catch (...) {
      std::error_code ec;
      fs::remove(temp, ec);
      throw;
    }
  }

  fs::path out_;
  ArchiveOptions options_;
  Database db_;
  Batcher batch_;
  mutable std::optional<Statement> has_;
  std::optional<Statement> put_;
  bool finished_ = false;
};

class PMTilesReader final : public TileReader {
 public:
  explicit PMTilesReader(const fs::path& path) : path_(path), in_(path, std::ios::binary) {
    if (!in_) fail(path, "cannot open");
    try {
      h_ = pmtiles::decode_header(read(0, pmtiles::kHeaderBytes));
      if (h_.internal_compression != pmtiles::Compression::Gzip)
        fail(path, "internal compression other than gzip is not supported");
      collect(pmtiles::decode_directory(pmtiles::gunzip(read(h_.root_offset, h_.root_length))), 0);
      m_ = metadata_from_json(pmtiles::gunzip(read(h_.metadata_offset, h_.metadata_length)),
                              path.string());
    } catch (const TileArchiveError& e) {  // the format's own errors name no file
      if (std::string_view(e.what()).starts_with("PMTiles")) fail(path, e.what());
      throw;
    }
    m_.minzoom = h_.min_zoom;
    m_.maxzoom = h_.max_zoom;
    const auto deg = [](std::int32_t e7) { return e7 / 1e7; };
    m_.bounds = {deg(h_.min_lon_e7), deg(h_.min_lat_e7), deg(h_.max_lon_e7), deg(h_.max_lat_e7)};
    m_.center = {deg(h_.center_lon_e7), deg(h_.center_lat_e7), h_.center_zoom};
  }

  const pmtiles::Header& header() const { return h_; }
  const TileMetadata& metadata() const override { return m_; }

  std::vector<TileId> tiles() const override {
    std::vector<TileId> out;
    for (const auto& e : entries_)
      for (std::uint32_t i = 0; i < e.run_length; ++i) out.push_back(pmtiles::tile_of(e.tile_id + i));
    std::sort(out.begin(), out.end());
    return out;
  }

  std::optional<std::string> get(const TileId& t) const override {
    if (!is_valid(t)) return std::nullopt;
    const std::uint64_t id = pmtiles::tile_id(t);
    auto it = std::upper_bound(entries_.begin(), entries_.end(), id,
                               [](std::uint64_t v, const Entry& e) { return v < e.tile_id; });
    if (it == entries_.begin()) return std::nullopt;
    --it;
    if (id >= it->tile_id + it->run_length) return std::nullopt;
    return read(h_.data_offset + it->offset, it->length);
  }

 private:
  std::string read(std::uint64_t offset, std::uint64_t length) const {
    std::string out(length, '\0');
    in_.clear();
    in_.seekg(static_cast<std::streamoff>(offset));
    in_.read(out.data(), static_cast<std::streamsize>(length));
    if (static_cast<std::uint64_t>(in_.gcount()) != length) fail(path_, "is truncated");
    return out;
  }

  // Tile entries in id order; leaves (one level, as the spec recommends) read in place.
  void collect(const std::vector<Entry>& dir, int depth) {
    for (const auto& e : dir) {
      if (e.run_length > 0) {
        entries_.push_back(e);
      } else if (depth == 0) {
        collect(pmtiles::decode_directory(pmtiles::gunzip(read(h_.leaves_offset + e.offset, e.length))), 1);
      } else {
        fail(path_, "has more than one level of leaf directories");
      }
    }
  }

  fs::path path_;
  mutable std::ifstream in_;
  pmtiles::Header h_;
  TileMetadata m_;
  std::vector<Entry> entries_;
};

}  // namespace

std::unique_ptr<TileArchive> open_pmtiles_archive(const fs::path& path, const ArchiveOptions& options) {
  return std::make_unique<PMTilesArchive>(path, options);
}

std::unique_ptr<TileReader> open_pmtiles_reader(const fs::path& path) {
  return std::make_unique<PMTilesReader>(path);
}

}  // namespace skylit::tiles::detail
