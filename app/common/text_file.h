// Text outputs written atomically (temp + rename: an interrupted or failed run leaves
// no partial file), shared by the front ends' CSV, SVG and JSON outputs.
#pragma once

#include <string>

namespace skylit::app {

// Throws std::runtime_error ("cannot write <what> '<path>': <reason>", one line) unless a
// file can be created next to `path` (checked before any work, so that a bad path
// fails fast and leaves nothing behind).
void check_writable(const std::string& path, const std::string& what);
// Writes `<path>.tmp-<pid>` and renames it over `path`; throws like check_writable.
void write_text_atomically(const std::string& path, const std::string& text, const std::string& what);

}  // namespace skylit::app
