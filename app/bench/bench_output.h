// Outputs of `skylit bench`: the aligned table on stdout and the CSV (written through
// app/common/text_file.h).
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

}  // namespace skylit::app::bench
