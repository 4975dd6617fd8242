#include "app/common/text_file.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

namespace skylit::app {
namespace {

std::string temp_name(const std::string& path) { return path + ".tmp-" + std::to_string(::getpid()); }

[[noreturn]] void fail(const std::string& what, const std::string& path, const std::string& reason) {
  throw std::runtime_error("cannot write " + what + " '" + path + "': " + reason);
}

// Writes `text` to `file`; returns why it failed ("" on success), leaving no file then.
std::string write_file(const std::string& file, const std::string& text) {
  errno = 0;
  std::ofstream f(file, std::ios::binary | std::ios::trunc);
  if (!f) return errno ? std::strerror(errno) : "cannot open";
  f << text;
  f.close();
  if (f) return "";
  std::error_code ignored;
  std::filesystem::remove(file, ignored);
  return "write failed";
}

}  // namespace

void check_writable(const std::string& path, const std::string& what) {
  if (path.empty()) fail(what, path, "empty path");
  if (std::filesystem::is_directory(path)) fail(what, path, "is a directory");
  const std::string probe = temp_name(path);
  if (const std::string why = write_file(probe, ""); !why.empty()) fail(what, path, why);
  std::error_code ignored;
  std::filesystem::remove(probe, ignored);
}

void write_text_atomically(const std::string& path, const std::string& text, const std::string& what) {
  const std::string temp = temp_name(path);
  if (const std::string why = write_file(temp, text); !why.empty()) fail(what, path, why);
  std::error_code ec;
  std::filesystem::rename(temp, path, ec);
  if (ec) {
    const std::string why = ec.message();
    std::filesystem::remove(temp, ec);
    fail(what, path, why);
  }
}

}  // namespace skylit::app
