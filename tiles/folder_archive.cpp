// A folder of tiles {z}/{x}/{y}.EXT (y in the XYZ or TMS row order) and metadata.json.
// Each tile is written to a hidden temporary in its own folder and renamed into place,
// so a tile file exists only complete: has() can trust every file it sees, and a
// resumed run deletes the temporaries a killed one left.
#include <algorithm>
#include <charconv>
#include <system_error>

#include "tiles/archive_kinds.h"
#include "tiles/file_io.h"
#include "tiles/fingerprint.h"

namespace skylit::tiles::detail {
namespace {

namespace fs = std::filesystem;

constexpr const char* kMetadataFile = "metadata.json";
constexpr const char* kSchemeKey = "scheme";

std::string_view scheme_name(Scheme s) { return s == Scheme::Tms ? "tms" : "xyz"; }

bool is_temp(const fs::path& p) {
  const std::string name = p.filename().string();
  return name.starts_with('.') && name.find(kTempTileMarker) != std::string::npos;
}

std::optional<int> parse_number(std::string_view s) {
  int v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || s.empty()) return std::nullopt;
  return v;
}

fs::path tile_path(const fs::path& root, const TileId& t, Scheme scheme, TileFormat format) {
  const int row = scheme == Scheme::Tms ? terrain::tms_y(t.z, t.y) : t.y;
  return root / std::to_string(t.z) / std::to_string(t.x) /
         (std::to_string(row) + "." + std::string(format_name(format)));
}

// Overwrite deletes only what this kind writes: a mistyped path must not cost a folder
// of someone's files.
void clear_tile_folder(const fs::path& root) {
  for (const auto& e : fs::directory_iterator(root)) {
    const std::string name = e.path().filename().string();
    const bool ours = name == kMetadataFile || name == kFingerprintFile || is_temp(e.path()) ||
                      (e.is_directory() && parse_number(name).has_value());
    if (!ours)
      fail(root, "holds '" + name + "', which a tile folder does not; not deleting it");
  }
  for (const auto& e : fs::directory_iterator(root)) fs::remove_all(e.path());
}

void remove_temporaries(const fs::path& root) {
  std::vector<fs::path> temps;
  for (const auto& e : fs::recursive_directory_iterator(root))
    if (e.is_regular_file() && is_temp(e.path())) temps.push_back(e.path());
  for (const auto& p : temps) remove_file(p);
}

class FolderArchive final : public TileArchive {
 public:
  FolderArchive(fs::path root, const ArchiveOptions& options)
      : root_(std::move(root)), options_(options) {
    std::error_code ec;
    const auto status = fs::status(root_, ec);
    if (fs::exists(status)) {
      if (!fs::is_directory(status)) fail(root_, "exists and is not a folder");
      switch (options_.mode) {
        case OpenMode::Create:
          fail(root_, "exists (overwrite it, or resume the run that wrote it)", "overwrite");
        case OpenMode::Overwrite: clear_tile_folder(root_); break;
        case OpenMode::Resume:
          // Checked before anything is removed; an empty folder is a fresh start.
          if (!fs::is_empty(root_)) check_resume_fingerprint(root_, stored_fingerprint(), options_.fingerprint);
          remove_temporaries(root_);
          break;
      }
    }
    fs::create_directories(root_, ec);
    if (ec) fail(root_, "cannot create the folder: " + ec.message());
    // Recorded before the first tile, so that a killed run's folder carries it.
    if (!options_.fingerprint.empty() && !stored_fingerprint())
      write_file_atomic(root_ / kFingerprintFile, as_bytes(options_.fingerprint), true);
  }

  bool has(const TileId& t) const override {
    std::error_code ec;
    return is_valid(t) && fs::is_regular_file(tile_path(root_, t, options_.scheme, options_.format), ec);
  }

  void put(const TileId& t, std::span<const std::byte> bytes) override {
    if (finished_) fail(root_, "put after finish");
    check_tile(root_, t, bytes);
    const fs::path path = tile_path(root_, t, options_.scheme, options_.format);
    if (path.parent_path() != last_dir_) {
      std::error_code ec;
      fs::create_directories(path.parent_path(), ec);
      if (ec) fail(path.parent_path(), "cannot create the folder: " + ec.message());
      last_dir_ = path.parent_path();
    }
    // No fsync per tile: the rename already protects against a killed process, which
    // is what resume handles; syncing every tile would cost more than rendering it.
    write_file_atomic(path, bytes, false);
  }

  void finish(const TileMetadata& metadata) override {
    if (finished_) fail(root_, "finished twice");
    check_metadata(root_, metadata, options_);
    const std::string json = metadata_to_json(metadata, kSchemeKey, scheme_name(options_.scheme));
    write_file_atomic(root_ / kMetadataFile, as_bytes(json), true);
    finished_ = true;
  }

 private:
  std::optional<std::string> stored_fingerprint() const {
    const fs::path p = root_ / kFingerprintFile;
    std::error_code ec;
    if (!fs::is_regular_file(p, ec)) return std::nullopt;
    return read_file(p);
  }

  fs::path root_;
  ArchiveOptions options_;
  fs::path last_dir_;
  bool finished_ = false;
};

class FolderReader final : public TileReader {
 public:
  explicit FolderReader(fs::path root) : root_(std::move(root)) {
    const fs::path meta = root_ / kMetadataFile;
    if (!fs::is_regular_file(meta)) fail(root_, "has no metadata.json (not a finished tile folder)");
    const std::string json = read_file(meta);
    metadata_ = metadata_from_json(json, meta.string());
    const auto scheme = json_string_member(json, kSchemeKey).value_or("xyz");
    if (scheme != "xyz" && scheme != "tms") fail(meta, "unknown scheme '" + scheme + "'");
    scheme_ = scheme == "tms" ? Scheme::Tms : Scheme::Xyz;
  }

  const TileMetadata& metadata() const override { return metadata_; }

  std::vector<TileId> tiles() const override {
    std::string ext(1, '.');
    ext += format_name(metadata_.format);
    std::vector<TileId> out;
    for (const auto& ze : fs::directory_iterator(root_)) {
      const auto z = parse_number(ze.path().filename().string());
      if (!ze.is_directory() || !z) continue;
      for (const auto& xe : fs::directory_iterator(ze.path())) {
        const auto x = parse_number(xe.path().filename().string());
        if (!xe.is_directory() || !x) continue;
        for (const auto& ye : fs::directory_iterator(xe.path())) {
          const std::string name = ye.path().filename().string();
          if (!ye.is_regular_file() || !name.ends_with(ext)) continue;
          const auto row = parse_number(std::string_view(name).substr(0, name.size() - ext.size()));
          if (!row) continue;
          TileId t{*z, *x, *row};
          if (!is_valid(t)) continue;
          if (scheme_ == Scheme::Tms) t.y = terrain::tms_y(t.z, t.y);
          out.push_back(t);
        }
      }
    }
    std::sort(out.begin(), out.end());
    return out;
  }

  std::optional<std::string> get(const TileId& t) const override {
    if (!is_valid(t)) return std::nullopt;
    const fs::path p = tile_path(root_, t, scheme_, metadata_.format);
    std::error_code ec;
    if (!fs::is_regular_file(p, ec)) return std::nullopt;
    return read_file(p);
  }

 private:
  fs::path root_;
  TileMetadata metadata_;
  Scheme scheme_ = Scheme::Xyz;
};

}  // namespace

std::unique_ptr<TileArchive> open_folder_archive(const fs::path& root, const ArchiveOptions& options) {
  return std::make_unique<FolderArchive>(root, options);
}

std::unique_ptr<TileReader> open_folder_reader(const fs::path& root) {
  return std::make_unique<FolderReader>(root);
}

}  // namespace skylit::tiles::detail
