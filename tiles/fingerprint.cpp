#include "tiles/fingerprint.h"

#include <map>
#include <sstream>
#include <vector>

#include "tiles/archive.h"

namespace skylit::tiles {
namespace {

// key → value, and the keys in their order of first appearance.
struct Lines {
  std::map<std::string, std::string> values;
  std::vector<std::string> order;
};

Lines parse(const std::string& text) {
  Lines l;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    const auto eq = line.find('=');
    const std::string key = line.substr(0, eq), value = eq == std::string::npos ? "" : line.substr(eq + 1);
    if (l.values.emplace(key, value).second) l.order.push_back(key);
  }
  return l;
}

}  // namespace

std::optional<std::string> fingerprint_difference(const std::string& stored, const std::string& wanted,
                                                  const std::string& stored_side, const std::string& wanted_side) {
  if (stored == wanted) return std::nullopt;
  const Lines a = parse(stored), b = parse(wanted);
  const auto value = [](const Lines& l, const std::string& key) {
    const auto it = l.values.find(key);
    return it == l.values.end() ? std::string("(none)") : it->second;
  };
  std::vector<std::string> keys = b.order;
  keys.insert(keys.end(), a.order.begin(), a.order.end());
  for (const auto& key : keys)
    if (value(a, key) != value(b, key))
      return key + ": " + value(a, key) + " in " + stored_side + ", " + value(b, key) + " in " + wanted_side;
  return "the recorded options differ in their order";  // same lines, other order or duplicates
}

void check_resume_fingerprint(const std::filesystem::path& archive, const std::optional<std::string>& stored,
                              const std::string& wanted) {
  if (wanted.empty()) return;
  const std::string where = std::string("'") + archive.string() + "': ";
  if (!stored)
    throw TileArchiveError(where + "cannot resume: it records no run options (made by another program or an older "
                                   "skylit); pass --overwrite to start afresh",
                           "overwrite");
  if (const auto diff = fingerprint_difference(*stored, wanted))
    throw TileArchiveError(where + "cannot resume with other options: " + *diff + " (pass --overwrite to start afresh)",
                           "overwrite");
}

}  // namespace skylit::tiles
