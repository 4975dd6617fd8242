// libFuzzer target for the GPX reader (flight/gpx_reader.h).
#include "flight/gpx_reader.h"
#include "fuzz/fuzz_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return skylit::fuzz::read_one_input(skylit::flight::read_gpx, data, size);
}
