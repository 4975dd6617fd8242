#include "tiles/file_io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "tiles/archive.h"

namespace skylit::tiles::detail {

namespace fs = std::filesystem;

void fail(const fs::path& path, const std::string& what, std::string option) {
  throw TileArchiveError("'" + path.string() + "': " + what, std::move(option));
}

void fail_errno(const fs::path& path, const std::string& what) {
  fail(path, what + ": " + std::strerror(errno));
}

File::File(const fs::path& path, int flags, int mode, const fs::path& shown)
    : path_(shown.empty() ? path : shown) {
  fd_ = ::open(path.c_str(), flags | O_CLOEXEC, mode);
  if (fd_ < 0) fail_errno(path, "cannot open");
}

File::~File() {
  if (fd_ >= 0) ::close(fd_);
}

void File::write(std::span<const std::byte> bytes) {
  const auto* p = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    const ssize_t n = ::write(fd_, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail_errno(path_, "cannot write");
    p += n;
    left -= static_cast<std::size_t>(n);
  }
}

void File::write(const std::string& bytes) {
  write(std::as_bytes(std::span<const char>(bytes.data(), bytes.size())));
}

void File::sync() {
  if (::fsync(fd_) != 0) fail_errno(path_, "cannot sync");
}

void File::close() {
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail_errno(path_, "cannot close");
}

void write_file_atomic(const fs::path& path, std::span<const std::byte> bytes, bool sync) {
  // mkstemp in the target's folder: rename() is atomic only within one file system.
  std::string name = path.parent_path() / ".";
  name += path.filename().string();
  name += kTempTileMarker;
  name += "XXXXXX";
  const int fd = ::mkstemp(name.data());
  if (fd < 0) fail_errno(path, "cannot create a temporary file");
  ::fchmod(fd, 0644);  // mkstemp's 0600 would hide tiles from a web server's user
  ::close(fd);
  const fs::path temp = name;
  try {
    File f(temp, O_WRONLY | O_TRUNC, 0644, path);
    f.write(bytes);
    if (sync) f.sync();
    f.close();
    if (::rename(temp.c_str(), path.c_str()) != 0) fail_errno(path, "cannot rename into place");
  } catch (...) {
    std::error_code ec;
    fs::remove(temp, ec);
    throw;
  }
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail_errno(path, "cannot open");
  std::ostringstream out;
  out << in.rdbuf();
  if (in.bad()) fail_errno(path, "cannot read");
  return std::move(out).str();
}

void remove_file(const fs::path& path) {
  std::error_code ec;
  fs::remove(path, ec);
  if (ec) fail(path, "cannot remove: " + ec.message());
}

fs::path with_suffix(const fs::path& path, const char* suffix) {
  fs::path out = path;
  out += suffix;
  return out;
}

}  // namespace skylit::tiles::detail
