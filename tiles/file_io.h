// File helpers shared by the archive kinds: whole writes that report errno in one
// line, and temporary-then-rename so that a file appears at its path only complete.
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>

namespace skylit::tiles::detail {

// Suffixes of the files a run keeps next to a file archive until finish(): the
// resumable state (an SQLite database) and the archive being assembled.
inline constexpr const char* kPartialSuffix = ".partial";
inline constexpr const char* kAssemblySuffix = ".assembling";
// Marks a folder's temporary tile files: ".<y>.<ext>.tmp-XXXXXX" (never a tile name).
inline constexpr const char* kTempTileMarker = ".tmp-";

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what,
                       std::string option = {});
// fail() with strerror(errno) appended.
[[noreturn]] void fail_errno(const std::filesystem::path& path, const std::string& what);

// An open file descriptor, closed on destruction.
class File {
 public:
  // `shown`: the name errors give (a temporary's target), when not `path` itself.
  File(const std::filesystem::path& path, int flags, int mode = 0644,
       const std::filesystem::path& shown = {});
  ~File();
  File(const File&) = delete;
  File& operator=(const File&) = delete;
  void write(std::span<const std::byte> bytes);  // all of it, or throws
  void write(const std::string& bytes);
  void sync();   // fsync: the data is on disk before a rename publishes it
  void close();  // reports close()'s error (NFS, quota) instead of dropping it
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
};

// Writes `bytes` to a unique temporary next to `path`, then renames it over `path`;
// the temporary is removed on failure. sync: fsync before the rename.
void write_file_atomic(const std::filesystem::path& path, std::span<const std::byte> bytes,
                       bool sync);

std::string read_file(const std::filesystem::path& path);

// Removes `path` (a file) if present; throws on any error other than absence.
void remove_file(const std::filesystem::path& path);

// `path` with `suffix` appended to its file name ("a.mbtiles" → "a.mbtiles.partial").
std::filesystem::path with_suffix(const std::filesystem::path& path, const char* suffix);

}  // namespace skylit::tiles::detail
