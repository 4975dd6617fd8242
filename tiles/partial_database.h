// The resumable state of a file archive (MBTiles, PMTiles): an SQLite database
// "OUT.partial" next to OUT until finish() (internal).
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "tiles/archive.h"

namespace skylit::tiles::detail {

// Removes an SQLite database file and its rollback journal, if present.
void remove_database(const std::filesystem::path& db);

// OUT's partial database path, prepared for `mode`: Create refuses an existing OUT or
// partial (one line naming the mode that fixes it), Overwrite removes the partial,
// Resume keeps it; resuming a finished OUT that has no partial, `import_finished(out,
// partial)` makes one from it (each kind its own way), after `finished_fingerprint(out)`
// passed check_resume_fingerprint against `fingerprint`: a refused resume leaves no
// partial behind. An existing partial is checked by the kind once it has opened it
// (SQLite must first roll back what a killed run left).
using ImportFinished = std::function<void(const std::filesystem::path& out, const std::filesystem::path& partial)>;
using ReadFingerprint = std::function<std::optional<std::string>(const std::filesystem::path& out)>;
std::filesystem::path prepare_partial(const std::filesystem::path& out, OpenMode mode,
                                      const ImportFinished& import_finished,
                                      const ReadFingerprint& finished_fingerprint, const std::string& fingerprint);

}  // namespace skylit::tiles::detail
