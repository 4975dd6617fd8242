// The options a tile run's bytes depend on, recorded in its archive so that a resumed
// run or a merge cannot mix tiles made with different ones (docs/tiles.md, "Existing
// output"). The text is one "key=value" line per option, in the writer's fixed order;
// the tiles library only stores and compares it (app/tiles/run_fingerprint.h makes it).
// Where it lives: MBTiles' metadata row and PMTiles' JSON metadata (kFingerprintKey, in
// TileMetadata), a folder's hidden file kFingerprintFile, and an interrupted file
// archive's partial database from the moment it is opened.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace skylit::tiles {

inline constexpr const char* kFingerprintKey = "skylit_fingerprint";
inline constexpr const char* kFingerprintFile = ".skylit-fingerprint";

// The first differing option, "zoom: 10-12 in the archive, 10-13 in this run" (a key
// only one side has reads "(none)" on the other); nullopt when the texts are equal.
std::optional<std::string> fingerprint_difference(const std::string& stored, const std::string& wanted,
                                                  const std::string& stored_side = "the archive",
                                                  const std::string& wanted_side = "this run");

// For OpenMode::Resume: throws TileArchiveError (one line, naming `archive` and the
// difference, option "overwrite") unless `stored` equals `wanted`. An empty `wanted`
// checks nothing (a caller that records no options); a missing `stored` is refused.
void check_resume_fingerprint(const std::filesystem::path& archive, const std::optional<std::string>& stored,
                              const std::string& wanted);

}  // namespace skylit::tiles
