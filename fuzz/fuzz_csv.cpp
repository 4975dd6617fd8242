// libFuzzer target for the CSV reader (flight/csv_reader.h).
#include "flight/csv_reader.h"
#include "fuzz/fuzz_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return skylit::fuzz::read_one_input(skylit::flight::read_csv, data, size);
}
