// MBTiles 1.3 (SQLite, TMS rows). Why the run writes to "OUT.partial" and renames it at
// finish(): the path OUT is then always either absent, the old complete archive, or
// the new complete one, never an unfinished database a viewer would show as done.
// The partial database is the resumable state: tiles are committed in batches, so a
// kill -9 at any moment leaves it valid with whole, committed tiles only (SQLite rolls
// a killed transaction back when the next run opens it), and a resumed run that puts
// the missing tiles ends with the same rows as an uninterrupted one. The metadata is
// written once, in finish()'s own transaction from the caller's full-run metadata, so
// a resume cannot leave an earlier run's partial metadata behind. Resuming a finished
// archive copies it to the partial path first (atomically), keeping OUT valid meanwhile.
#include <algorithm>
#include <charconv>
#include <cstdio>
#include <optional>
#include <system_error>

#include "tiles/archive_kinds.h"
#include "tiles/file_io.h"
#include "tiles/fingerprint.h"
#include "tiles/partial_database.h"
#include "tiles/sqlite_db.h"

namespace skylit::tiles::detail {
namespace {

namespace fs = std::filesystem;

// MBTiles 1.3: "MAY use the application_id 0x4d504258" ("MPBX").
constexpr const char* kSchema = R"sql(
PRAGMA application_id = 0x4d504258;
CREATE TABLE IF NOT EXISTS metadata (name text, value text);
CREATE TABLE IF NOT EXISTS tiles (zoom_level integer, tile_column integer, tile_row integer,
                                  tile_data blob);
CREATE UNIQUE INDEX IF NOT EXISTS tile_index ON tiles (zoom_level, tile_column, tile_row);
)sql";

std::string number(double v) {  // shortest text that reads back as v
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::vector<double> numbers(const std::string& csv) {
  std::vector<double> out;
  const char* p = csv.data();
  const char* end = p + csv.size();
  while (p < end) {
    while (p < end && *p == ' ') ++p;
    double v = 0;
    const auto r = std::from_chars(p, end, v);
    if (r.ec != std::errc()) return {};
    out.push_back(v);
    p = r.ptr;
    while (p < end && *p == ' ') ++p;
    if (p < end && *p++ != ',') return {};
  }
  return out;
}

// Resuming a finished archive: a copy becomes the partial database (copied beside it and
// renamed, so OUT stays valid and no half copy is ever the partial).
void copy_to_partial(const fs::path& out, const fs::path& partial) {
  const fs::path copy = with_suffix(out, kAssemblySuffix);
  std::error_code ec;
  fs::copy_file(out, copy, fs::copy_options::overwrite_existing, ec);
  if (!ec) fs::rename(copy, partial, ec);
  if (ec) {
    fs::remove(copy);
    fail(out, "cannot copy it to resume it: " + ec.message());
  }
}

class MBTilesArchive final : public TileArchive {
 public:
  MBTilesArchive(const fs::path& out, const ArchiveOptions& options)
      : out_(out), options_(options),
        db_(prepare_partial(out, options.mode, copy_to_partial, finished_fingerprint, options.fingerprint)),
        batch_(db_, options.batch_tiles) {
    const bool fresh = !Statement(db_, "SELECT 1 FROM sqlite_master WHERE name = 'metadata'").step();
    // Checked before the schema: its PRAGMA writes the header, and a refused resume
    // must leave the partial's bytes as they were.
    if (!fresh && options_.mode == OpenMode::Resume && !options_.fingerprint.empty())
      check_resume_fingerprint(out_, stored_fingerprint(), options_.fingerprint);
    db_.exec(kSchema);
    // A new partial records the options now, so that a killed run's partial carries them.
    if (!options_.fingerprint.empty() && !stored_fingerprint())
      Statement(db_, "INSERT INTO metadata (name, value) VALUES (?, ?)")
          .bind(1, std::string(kFingerprintKey))
          .bind(2, options_.fingerprint)
          .run();
    has_.emplace(db_, "SELECT 1 FROM tiles WHERE zoom_level = ? AND tile_column = ? AND tile_row = ?");
    put_.emplace(db_,
                 "INSERT OR REPLACE INTO tiles (zoom_level, tile_column, tile_row, tile_data) "
                 "VALUES (?, ?, ?, ?)");
  }

  bool has(const TileId& t) const override {
    if (!is_valid(t)) return false;
    bind(*has_, t);
    const bool found = has_->step();
    has_->reset();
    return found;
  }

  void put(const TileId& t, std::span<const std::byte> bytes) override {
    if (finished_) fail(out_, "put after finish");
    check_tile(out_, t, bytes);
    batch_.begin();
    bind(*put_, t).bind_blob(4, bytes).run();
    batch_.wrote();
  }

  void finish(const TileMetadata& m) override {
    if (finished_) fail(out_, "finished twice");
    check_metadata(out_, m, options_);
    batch_.commit();
    // The partial's fingerprint row goes with the rest: the finished metadata has its own.
    db_.exec("BEGIN; DELETE FROM metadata;");
    write_metadata(m);
    db_.exec("COMMIT");
    has_.reset();  // statements must be finalized before the database closes
    put_.reset();
    const fs::path partial = db_.path();
    db_.close();
    std::error_code ec;
    fs::rename(partial, out_, ec);
    if (ec) fail(out_, "cannot rename '" + partial.string() + "' into place: " + ec.message());
    finished_ = true;
  }

 private:
  static std::optional<std::string> finished_fingerprint(const fs::path& out) {
    return open_mbtiles_reader(out)->metadata().fingerprint;
  }

  std::optional<std::string> stored_fingerprint() {
    Statement get(db_, "SELECT value FROM metadata WHERE name = ?");
    get.bind(1, std::string(kFingerprintKey));
    return get.step() ? std::optional(get.column_text(0)) : std::nullopt;
  }

  void write_metadata(const TileMetadata& m) {
    Statement row(db_, "INSERT INTO metadata (name, value) VALUES (?, ?)");
    const auto add = [&](const std::string& name, const std::string& value) {
      row.bind(1, name).bind(2, value).run();
    };
    add("name", m.name);
    add("format", std::string(format_name(m.format)));
    add("bounds", number(m.bounds.west) + "," + number(m.bounds.south) + "," +
                      number(m.bounds.east) + "," + number(m.bounds.north));
    add("center", number(m.center.lon) + "," + number(m.center.lat) + "," +
                      std::to_string(m.center.zoom));
    add("minzoom", std::to_string(m.minzoom));
    add("maxzoom", std::to_string(m.maxzoom));
    if (m.description) add("description", *m.description);
    if (m.attribution) add("attribution", *m.attribution);
    if (m.type) add("type", *m.type);
    if (m.fingerprint) add(kFingerprintKey, *m.fingerprint);
  }

  static Statement& bind(Statement& s, const TileId& t) {
    return s.bind(1, t.z).bind(2, t.x).bind(3, terrain::tms_y(t.z, t.y));
  }

  fs::path out_;
  ArchiveOptions options_;
  Database db_;
  Batcher batch_;
  mutable std::optional<Statement> has_;
  std::optional<Statement> put_;
  bool finished_ = false;
};

class MBTilesReader final : public TileReader {
 public:
  explicit MBTilesReader(const fs::path& path) : db_(open_existing(path), true) {
    Statement rows(db_, "SELECT name, value FROM metadata");
    std::optional<std::string> name, format;
    while (rows.step()) {
      const std::string key = rows.column_text(0), value = rows.column_text(1);
      const auto coords = numbers(value);
      if (key == "name") name = value;
      else if (key == "format") format = value;
      else if (key == "bounds" && coords.size() == 4) m_.bounds = {coords[0], coords[1], coords[2], coords[3]};
      else if (key == "center" && coords.size() == 3)
        m_.center = {coords[0], coords[1], static_cast<int>(coords[2])};
      else if (key == "minzoom" && coords.size() == 1) m_.minzoom = static_cast<int>(coords[0]);
      else if (key == "maxzoom" && coords.size() == 1) m_.maxzoom = static_cast<int>(coords[0]);
      else if (key == "description") m_.description = value;
      else if (key == "attribution") m_.attribution = value;
      else if (key == "type") m_.type = value;
      else if (key == kFingerprintKey) m_.fingerprint = value;
    }
    if (!name || !format) fail(path, "has no name or format in its metadata (not a finished MBTiles)");
    m_.name = *name;
    m_.format = parse_format(*format);
  }

  const TileMetadata& metadata() const override { return m_; }

  std::vector<TileId> tiles() const override {
    Statement rows(db_, "SELECT zoom_level, tile_column, tile_row FROM tiles");
    std::vector<TileId> out;
    while (rows.step()) {
      const auto z = rows.column_int(0), x = rows.column_int(1), row = rows.column_int(2);
      // Out-of-int values become −1 so that is_valid() refuses them rather than wrapping.
      const auto narrow = [](std::int64_t v) {
        return v >= 0 && v < (std::int64_t{1} << terrain::kMaxTileZoom) ? static_cast<int>(v) : -1;
      };
      TileId t{narrow(z), narrow(x), narrow(row)};
      if (!is_valid(t)) fail(db_.path(), "holds a tile outside its zoom's grid");
      t.y = terrain::tms_y(t.z, t.y);
      out.push_back(t);
    }
    std::sort(out.begin(), out.end());
    return out;
  }

  std::optional<std::string> get(const TileId& t) const override {
    if (!is_valid(t)) return std::nullopt;
    Statement s(db_, "SELECT tile_data FROM tiles WHERE zoom_level = ? AND tile_column = ? AND tile_row = ?");
    s.bind(1, t.z).bind(2, t.x).bind(3, terrain::tms_y(t.z, t.y));
    if (!s.step()) return std::nullopt;
    return s.column_text(0);
  }

 private:
  static const fs::path& open_existing(const fs::path& path) {
    if (!fs::is_regular_file(path)) fail(path, "does not exist");
    return path;
  }

  mutable Database db_;
  TileMetadata m_;
};

}  // namespace

std::unique_ptr<TileArchive> open_mbtiles_archive(const fs::path& path, const ArchiveOptions& options) {
  return std::make_unique<MBTilesArchive>(path, options);
}

std::unique_ptr<TileReader> open_mbtiles_reader(const fs::path& path) {
  return std::make_unique<MBTilesReader>(path);
}

}  // namespace skylit::tiles::detail
