#include "tiles/partial_database.h"

#include "tiles/file_io.h"
#include "tiles/fingerprint.h"

namespace skylit::tiles::detail {

namespace fs = std::filesystem;

void remove_database(const fs::path& db) {
  remove_file(db);
  remove_file(with_suffix(db, "-journal"));
}

fs::path prepare_partial(const fs::path& out, OpenMode mode, const ImportFinished& import_finished,
                         const ReadFingerprint& finished_fingerprint, const std::string& fingerprint) {
  const fs::path partial = with_suffix(out, kPartialSuffix);
  const bool have_out = fs::exists(out), have_partial = fs::exists(partial);
  switch (mode) {
    case OpenMode::Create:
      if (have_out) fail(out, "exists (overwrite it, or resume the run that wrote it)", "overwrite");
      if (have_partial)
        fail(out, "an interrupted run left '" + partial.string() + "' (resume or overwrite it)", "resume");
      break;
    case OpenMode::Overwrite: remove_database(partial); break;
    case OpenMode::Resume:
      if (!have_partial && have_out) {
        if (!fingerprint.empty()) check_resume_fingerprint(out, finished_fingerprint(out), fingerprint);
        import_finished(out, partial);
      }
      break;
  }
  return partial;
}

}  // namespace skylit::tiles::detail
