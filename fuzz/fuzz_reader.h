// The body every reader's fuzz target shares: the input as a stream, the reader's
// documented failure (std::invalid_argument, one line) caught; anything else — another
// exception, a crash, a sanitizer report, a hang — is a bug the fuzzer reports.
#pragma once

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

namespace skylit::fuzz {

template <class Reader>
int read_one_input(Reader read, const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    const auto tracks = read(in, "fuzz");
    for (const auto& t : tracks)
      // Readers never return an empty track, nor a name that would break a line.
      if (t.fixes.empty() || t.id.find_first_of("\n\r") != std::string::npos) __builtin_trap();
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    if (what.find_first_of("\n\r") != std::string::npos) __builtin_trap();  // errors are one line
  }
  return 0;
}

}  // namespace skylit::fuzz
