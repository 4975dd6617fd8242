// Outputs of `skylit bench`: the aligned table on stdout, the CSV, and atomic text
// files (temp + rename: an interrupted or failed run leaves no partial file).
#pragma once

#include "app/bench/bench_run.h"

#include <ostream>
#include <string>
#include <vector>

namespace skylit::app::bench {

void print_table_header(std::ostream& out);
void print_table_row(std::ostream& out, const BenchRow& row);  // flushes: rows arrive slowly

// Header + one line per row; NA for errors without ground truth.
std::string csv_text(const std::vector<BenchRow>& rows);

// Throws std::runtime_error ("cannot write '<path>': <reason>", one line) unless a
// file can be created next to `path` (checked before any work, so that a bad path
// fails fast and leaves nothing behind).
void check_writable(const std::string& path, const std::string& what);
// Writes `<path>.tmp-<pid>` and renames it over `path`; throws like check_writable.
void write_text_atomically(const std::string& path, const std::string& text, const std::string& what);

}  // namespace skylit::app::bench
