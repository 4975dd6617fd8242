#include "app/common/frame_pattern.h"

#include <cctype>
#include <cstdio>
#include <stdexcept>

namespace skylit::app {

std::optional<std::pair<std::size_t, std::size_t>> frame_pattern(const std::string& path) {
  std::optional<std::pair<std::size_t, std::size_t>> found;
  for (std::size_t k = 0; k < path.size(); ++k) {
    if (path[k] != '%') continue;
    if (k + 1 < path.size() && path[k + 1] == '%') {
      ++k;
      continue;
    }
    std::size_t e = k + 1;
    while (e < path.size() && std::isdigit(static_cast<unsigned char>(path[e]))) ++e;
    if (e >= path.size() || path[e] != 'd' || e - k - 1 > 2)
      throw std::invalid_argument("output '" + path + "': only one %d, %0Nd or %Nd (N < 100) may stand for the frame number "
                                  "(write %% for a percent sign)");
    if (found) throw std::invalid_argument("output '" + path + "' has two frame numbers (%d): give one");
    found = std::pair{k, e + 1 - k};
    k = e;
  }
  return found;
}

std::string frame_path(const std::string& path, int frame) {
  const auto pattern = frame_pattern(path);
  std::string out;
  for (std::size_t k = 0; k < path.size(); ++k) {
    if (pattern && k == pattern->first) {
      const std::string spec = path.substr(k, pattern->second);
      char buf[128];
      std::snprintf(buf, sizeof buf, spec.c_str(), frame);  // spec is exactly %[0][N]d (checked)
      out += buf;
      k += pattern->second - 1;
    } else if (path[k] == '%' && k + 1 < path.size() && path[k + 1] == '%') {
      out += '%';
      ++k;
    } else {
      out += path[k];
    }
  }
  return out;
}

}  // namespace skylit::app
